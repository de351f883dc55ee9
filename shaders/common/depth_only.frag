#version 120
// Depth pre-pass: colour writes are masked off; the shader only has to exist.
#ifdef LIDR_ALPHA_MASK  // the material variant of a MASK material: cut out as the shading passes do
#include "output_transform.glsl"
#include "material.glsl"
#endif
#include "lidr_depth.glsl"
void main() {
#ifdef LIDR_ALPHA_MASK
    lidrAlphaTest(lidrBaseColor().a);
#endif
    lidrWriteDepth();
    gl_FragColor = vec4(0.0);
}
