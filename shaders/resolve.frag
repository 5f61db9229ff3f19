// Progressive sampling: the image so far. The mean of the passes summed in u_sum (rgb / alpha) is the
// lecture's L before the clamp; it is clamped and encoded as a one-pass frame would be. Pixels no
// pass covered show the background, as the cleared framebuffer of a one-pass frame does, and every
// pixel gets the surface's depth so the overlays drawn afterwards are hidden where they should be.
#include "encoding.glsl"

uniform sampler2D u_sum;
uniform sampler2D u_depth;    // the depth the first pass wrote (every pass draws the same surfaces)
uniform vec3 u_background;    // written as given, like glClearColor
out vec4 o_color;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 sum = texelFetch(u_sum, texel, 0);
    o_color = sum.a > 0.0 ? vec4(encodeOutput(clamp(sum.rgb / sum.a, 0.0, 1.0)), 1.0) : vec4(u_background, 1.0);
    gl_FragDepth = texelFetch(u_depth, texel, 0).r;
}
