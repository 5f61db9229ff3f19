// Layout "diff": |A - B| * factor of the two panes' displayed values, per channel, clamped to [0, 1].
// u_sourceA and u_sourceB hold copies of the two panes (the same size as this one); texelFetch reads
// the pixel at the same place in each, so the difference is of exactly the pixels on screen.
uniform sampler2D u_sourceA;
uniform sampler2D u_sourceB;
uniform ivec2 u_paneOrigin;  // this pane's lower-left corner in window coordinates
uniform float u_factor;
out vec4 o_color;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy) - u_paneOrigin;
    vec3 a = texelFetch(u_sourceA, texel, 0).rgb;
    vec3 b = texelFetch(u_sourceB, texel, 0).rgb;
    o_color = vec4(clamp(abs(a - b) * u_factor, 0.0, 1.0), 1.0);
}
