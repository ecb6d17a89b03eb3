#version 330 core
// One fullscreen triangle from gl_VertexID (no vertex buffer): the viewer draws the frame (the
// engine's, the twin's, or both composed) as a single texture covering its view. Row 0 of the
// frame is the top of the image, while OpenGL's texture origin is the bottom row, hence the flip
// of v.
out vec2 uv;
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));  // (0,0) (2,0) (0,2)
    // p in [0,1]² is the window; the triangle overhangs it and is clipped.
    uv = vec2(p.x, 1.0 - p.y);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
