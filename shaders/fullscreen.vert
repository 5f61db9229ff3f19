// One triangle covering the viewport, for the image passes (the diff pane, progressive sampling's
// accumulate and resolve): no vertex buffers, the positions come from gl_VertexID.
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
