#version 120
// The overlap probe counts pixels that pass its stencil test (an occlusion query); colour writes are off.
#include "lidr_depth.glsl"
void main() {
    lidrWriteDepth();
    gl_FragColor = vec4(0.0);
}
