// Unlit overlay lines: one colour per draw (see overlay.vert).
uniform vec4 u_overlayColor;  // linear RGB, alpha blended over the shaded image

out vec4 o_color;

void main() {
    o_color = u_overlayColor;
}
