#version 120
// One step of the per-tile min/max depth reduction: each output texel reduces LIDR_REDUCE_COUNT input
// texels along one axis (x when LIDR_REDUCE_VERTICAL is 0, then y), so two passes reduce T x T tiles for
// any tile size T. The loop has the constant bound GLSL ES 1.00-class compilers want and breaks at the
// input's edge (the last row and column of tiles may be partial).
//   LIDR_DEPTH_PACKED: one 24-bit packed depth per texel; LIDR_REDUCE_MAX picks the max chain (else min).
#include "depth_pack.glsl"

uniform sampler2D uInput;
uniform vec2 uInputSize;

void main() {
    vec2 cell = floor(gl_FragCoord.xy);
#if LIDR_REDUCE_VERTICAL
    vec2 first = vec2(cell.x, cell.y * float(LIDR_REDUCE_COUNT));
    vec2 step = vec2(0.0, 1.0);
#else
    vec2 first = vec2(cell.x * float(LIDR_REDUCE_COUNT), cell.y);
    vec2 step = vec2(1.0, 0.0);
#endif
    vec2 range = vec2(1e30, -1e30);  // (min, max)
    for (int i = 0; i < LIDR_REDUCE_COUNT; ++i) {
        vec2 p = first + step * float(i);
        if (p.x >= uInputSize.x || p.y >= uInputSize.y) break;
        vec4 texel = texture2D(uInput, (p + 0.5) / uInputSize);
#ifdef LIDR_DEPTH_PACKED
        float v = lidrUnpackDepthUnits(texel);
        range = vec2(min(range.x, v), max(range.y, v));
#else
        range = vec2(min(range.x, texel.r), max(range.y, texel.g));
#endif
    }
#ifdef LIDR_DEPTH_PACKED
#if LIDR_REDUCE_MAX
    gl_FragColor = lidrPackDepthUnits(range.y);
#else
    gl_FragColor = lidrPackDepthUnits(range.x);
#endif
#else
    gl_FragColor = vec4(range, 0.0, 1.0);
#endif
}
