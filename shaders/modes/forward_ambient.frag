#version 120
// Multi-pass forward, pass 0: the ambient term and the directional lights (not indexed), linear. The per-light
// passes add onto it; the output transform runs over the finished sum (output_encode.frag).
#include "shading.glsl"

void main() {
    LidrSurface s = lidrSurface();
    gl_FragColor = vec4(lidrAmbient(s) + lidrDirectionalLights(s), uMaterialOpacity);
}
