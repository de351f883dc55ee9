#version 120
// Depth pre-pass: colour writes are masked off; the shader only has to exist.
#include "lidr_depth.glsl"
void main() {
    lidrWriteDepth();
    gl_FragColor = vec4(0.0);
}
