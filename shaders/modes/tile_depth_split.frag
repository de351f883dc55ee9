#version 120
// Half-Z, first pass: each tile's depth range [min, max] (from the min/max reduction) is split at its middle;
// each output texel reduces LIDR_REDUCE_COUNT texels of the depth copy along x (one tile's columns of one
// row) to (the min of the depths at or beyond the middle, the max of those before it). The vertical step is
// tile_depth_reduce.frag: min of R, max of G. Empty halves keep their start values (1 and 0), which the CPU
// reads as "no depth there" (the near range is then [min, min], the far range always holds max).
//   LIDR_OUTPUT_PACKED  1: packed RGBA8 chains (min/max tile inputs packed too); LIDR_SPLIT_NEAR_MAX picks
//                       which value this chain writes (1: the near max, 0: the far min); 0: float RG
#include "depth_pack.glsl"

uniform sampler2D uInput;     // the packed depth copy (width x height)
uniform vec2 uInputSize;
uniform sampler2D uTileMin;   // tilesX x tilesY: float RG (min, max), or packed min
uniform sampler2D uTileMax;   // packed max (packed path only)
uniform vec2 uTileGridSize;

void main() {
    vec2 cell = floor(gl_FragCoord.xy);
    vec2 tileUv = (vec2(cell.x, floor(cell.y * (1.0 / float(LIDR_REDUCE_COUNT)))) + 0.5) / uTileGridSize;
#if LIDR_OUTPUT_PACKED
    float middle = 0.5 * (lidrUnpackDepthUnits(texture2D(uTileMin, tileUv)) +
                          lidrUnpackDepthUnits(texture2D(uTileMax, tileUv)));
    float scale = 1.0;  // work in packed units
#else
    vec4 range = texture2D(uTileMin, tileUv);
    float middle = 0.5 * (range.r + range.g);
    float scale = 1.0 / kLidrDepthUnits;  // work in [0, 1]
#endif
    float farMin = kLidrDepthUnits * scale, nearMax = 0.0;
    vec2 first = vec2(cell.x * float(LIDR_REDUCE_COUNT), cell.y);
    for (int i = 0; i < LIDR_REDUCE_COUNT; ++i) {
        vec2 p = first + vec2(float(i), 0.0);
        if (p.x >= uInputSize.x) break;
        float d = lidrUnpackDepthUnits(texture2D(uInput, (p + 0.5) / uInputSize)) * scale;
        if (d >= middle) farMin = min(farMin, d);
        else nearMax = max(nearMax, d);
    }
#if LIDR_OUTPUT_PACKED
#if LIDR_SPLIT_NEAR_MAX
    gl_FragColor = lidrPackDepthUnits(nearMax);
#else
    gl_FragColor = lidrPackDepthUnits(farMin);
#endif
#else
    gl_FragColor = vec4(farMin, nearMax, 0.0, 1.0);
#endif
}
