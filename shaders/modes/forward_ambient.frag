#version 120
// Multi-pass forward, pass 0: the ambient term alone. The per-light passes add onto it.
#include "shading.glsl"

void main() {
    LidrSurface s = lidrSurface();
    gl_FragColor = vec4(lidrAmbient(s), uMaterialOpacity);
}
