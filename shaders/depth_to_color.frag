#version 120
// Tiled pre-Z: the depth test and depth writes as in any depth pre-pass, and the fragment's window depth
// also written to a colour target, so the GPU can reduce it per tile (GL 2.1 cannot sample the packed
// depth-stencil renderbuffer). The nearest fragment is written last, so each pixel ends with its depth.
#include "depth_pack.glsl"

void main() {
#ifdef LIDR_DEPTH_PACKED
    gl_FragColor = lidrPackDepthUnits(floor(clamp(gl_FragCoord.z, 0.0, 1.0) * kLidrDepthUnits + 0.5));
#else
    gl_FragColor = vec4(gl_FragCoord.z, gl_FragCoord.z, 0.0, 1.0);
#endif
}
