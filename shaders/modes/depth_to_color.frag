#version 120
// Tiled pre-Z: the depth test and depth writes as in any depth pre-pass, and the fragment's window depth
// also written, packed in RGBA8 (depth_pack.glsl), to a colour texture the GPU then reduces per tile. The
// nearest fragment is written last, so each pixel ends with the depth the depth buffer keeps.
#ifdef LIDR_ALPHA_MASK  // the material variant of a MASK material: cut out as the shading passes do
#include "output_transform.glsl"
#include "material.glsl"
#endif
#include "depth_pack.glsl"

void main() {
#ifdef LIDR_ALPHA_MASK
    lidrAlphaTest(lidrBaseColor().a);
#endif
    gl_FragColor = lidrPackDepthUnits(floor(clamp(gl_FragCoord.z, 0.0, 1.0) * kLidrDepthUnits + 0.5));
}
