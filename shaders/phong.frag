// The interpolated normal is renormalised here, per fragment, before the model is evaluated.
// A double-sided surface seen from behind is lit with that normal flipped (SL_DOUBLE_SIDED).
#define SL_STAGE_IO in
#include "phong_interface.glsl"
#include "lighting.glsl"
#include "object_color.glsl"

out vec4 o_color;

void main() {
    if (cutOut()) discard;
    vec3 N = normalize(v_nrmWorld);
#if SL_DOUBLE_SIDED
    // glTF's doubleSided: the fragment shows the back of its triangle, so N points away from the eye's side.
    if (!gl_FrontFacing) N = -N;
#endif
#if SL_ACCUMULATE
    // A pass of progressive sampling: the estimate before the clamp, summed with the other passes'
    // in a float buffer; shaders/resolve.frag clamps and encodes the mean, as the line below does.
    o_color = vec4(shadeLectureUnclamped(v_posWorld, N, objectTexel()), 1.0);
#else
    o_color = vec4(encodeOutput(shadeLecture(v_posWorld, N, objectTexel())), outputAlpha());
#endif
}
