#version 330 core
// Shows the frame texel for texel (the engine's, the OpenGL twin's read back, or both composed):
// the texture is the frame's size and uses GL_NEAREST.
in vec2 uv;
uniform sampler2D frame;
out vec4 color;
void main() {
    color = vec4(texture(frame, uv).rgb, 1.0);
}
