#version 120
// Depth pre-pass: colour writes are masked off; the shader only has to exist.
void main() {
    gl_FragColor = vec4(0.0);
}
