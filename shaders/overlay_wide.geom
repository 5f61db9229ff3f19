// Overlay lines drawn u_lineWidth pixels wide, for a projector or a HiDPI screen: OpenGL 3.3 core
// rasterises lines one pixel wide only, so each segment becomes a quad facing the screen. The vertex
// and fragment stages are overlay.vert and overlay.frag, as for one-pixel lines.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 u_viewportSize;  // pixels of the pane
uniform float u_lineWidth;    // pixels

void main() {
    vec4 a = gl_in[0].gl_Position;
    vec4 b = gl_in[1].gl_Position;
    // A segment reaching behind the eye is cut just in front of it, where it can be measured on screen.
    const float nearW = 1e-4;
    if (a.w < nearW && b.w < nearW) return;
    if (a.w < nearW) a = mix(a, b, (nearW - a.w) / (b.w - a.w));
    if (b.w < nearW) b = mix(b, a, (nearW - b.w) / (a.w - b.w));
    // Direction on screen, in pixels; half the width across it and past each end (square caps).
    vec2 along = (b.xy / b.w - a.xy / a.w) * u_viewportSize;
    along = length(along) > 1e-6 ? normalize(along) : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    // Half a width in pixels is width / size in normalised device coordinates; times w in clip space.
    vec2 halfAcross = across * u_lineWidth / u_viewportSize;
    vec2 halfAlong = along * u_lineWidth / u_viewportSize;
    gl_Position = vec4(a.xy + (-halfAlong - halfAcross) * a.w, a.zw);
    EmitVertex();
    gl_Position = vec4(a.xy + (-halfAlong + halfAcross) * a.w, a.zw);
    EmitVertex();
    gl_Position = vec4(b.xy + (halfAlong - halfAcross) * b.w, b.zw);
    EmitVertex();
    gl_Position = vec4(b.xy + (halfAlong + halfAcross) * b.w, b.zw);
    EmitVertex();
    EndPrimitive();
}
