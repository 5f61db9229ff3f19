// The environment as the background (--environment): each pixel shows env(d) for the direction d the
// camera looks along through it (shaders/environment.glsl), clamped and encoded like a surface's L.
// Drawn over the cleared pane, before the scene's surfaces. It reads no uniform block (WebGL2 refuses a
// draw whose program has an active block without a large enough buffer bound): its three values are
// plain uniforms.
#include "encoding.glsl"
#include "environment.glsl"

uniform vec3 u_eyeWorld;       // the camera's position
uniform mat4 u_worldFromClip;  // the inverse of clipFromWorld, for this pane
uniform vec4 u_paneRect;       // the pane's viewport: x, y (GL's, from the bottom), width, height
out vec4 o_color;

void main() {
    vec2 ndc = (gl_FragCoord.xy - u_paneRect.xy) / u_paneRect.zw * 2.0 - 1.0;
    vec4 far = u_worldFromClip * vec4(ndc, 1.0, 1.0);
    vec3 d = normalize(far.xyz / far.w - u_eyeWorld);
    o_color = vec4(encodeOutput(clamp(environment(d), 0.0, 1.0)), 1.0);
    gl_FragDepth = 1.0;  // the far plane: after progressive sampling it fills only what no surface covers
}
