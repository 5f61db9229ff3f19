// The interpolated normal is renormalised here, per fragment, before the model is evaluated.
#define SL_STAGE_IO in
#include "phong_interface.glsl"
#include "lighting.glsl"
#include "object_color.glsl"

out vec4 o_color;

void main() {
    if (cutOut()) discard;
#if SL_ACCUMULATE
    // A pass of progressive sampling: the estimate before the clamp, summed with the other passes'
    // in a float buffer; shaders/resolve.frag clamps and encodes the mean, as the line below does.
    o_color = vec4(shadeLectureUnclamped(v_posWorld, normalize(v_nrmWorld), objectTexel()), 1.0);
#else
    o_color = vec4(encodeOutput(shadeLecture(v_posWorld, normalize(v_nrmWorld), objectTexel())), outputAlpha());
#endif
}
