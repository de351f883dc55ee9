#version 120
// One step of the per-tile min/max depth reduction: each output texel reduces LIDR_REDUCE_COUNT input
// texels along one axis (x when LIDR_REDUCE_VERTICAL is 0, then y), so two passes reduce T x T tiles for
// any tile size T. The loop has the constant bound GLSL ES 1.00-class compilers want and breaks at the
// input's edge (the last row and column of tiles may be partial).
//   LIDR_INPUT_PACKED   1: input texels hold one packed depth (depth_pack.glsl); 0: float (min, max) in RG
//   LIDR_OUTPUT_PACKED  1: write one packed depth, the max if LIDR_REDUCE_MAX else the min; 0: float RG
//   LIDR_INPUT_SPANS    1 (MSAA, first pass, packed input): each pixel counts the depths its samples shade, from
//                       the centre's packed depth and the MSAA depth spans (lidr/technique/depth_span_pass.h)
#include "depth_pack.glsl"

uniform sampler2D uInput;
uniform vec2 uInputSize;
#if LIDR_INPUT_SPANS
uniform sampler2D uSpans;
uniform float uSpanBoundScale;  // DepthSpanPass::boundScale()
#endif

void main() {
    vec2 cell = floor(gl_FragCoord.xy);
#if LIDR_REDUCE_VERTICAL
    vec2 first = vec2(cell.x, cell.y * float(LIDR_REDUCE_COUNT));
    vec2 step = vec2(0.0, 1.0);
#else
    vec2 first = vec2(cell.x * float(LIDR_REDUCE_COUNT), cell.y);
    vec2 step = vec2(1.0, 0.0);
#endif
    vec2 range = vec2(1e30, -1e30);  // (min, max), in packed units while the input is packed
    for (int i = 0; i < LIDR_REDUCE_COUNT; ++i) {
        vec2 p = first + step * float(i);
        if (p.x >= uInputSize.x || p.y >= uInputSize.y) break;
        vec4 texel = texture2D(uInput, (p + 0.5) / uInputSize);
#if LIDR_INPUT_PACKED
        float v = lidrUnpackDepthUnits(texel);
#if LIDR_INPUT_SPANS
        // The pixel's samples shade depths within [lo, hi] (units; one more each side for the packing's rounding);
        // background where none does.
        vec2 excess = texture2D(uSpans, (p + 0.5) / uInputSize).rg * (uSpanBoundScale * kLidrDepthUnits);
        bool centreSurface = v < kLidrDepthUnits;
        float lo = centreSurface ? v - excess.g : kLidrDepthUnits - excess.g;
        float hi = centreSurface ? v + excess.r : min(excess.r, kLidrDepthUnits);
        if (lo > hi) lo = hi = kLidrDepthUnits;
        range = vec2(min(range.x, max(lo - 1.0, 0.0)), max(range.y, min(hi + 1.0, kLidrDepthUnits)));
#else
        range = vec2(min(range.x, v), max(range.y, v));
#endif
#else
        range = vec2(min(range.x, texel.r), max(range.y, texel.g));
#endif
    }
#if LIDR_OUTPUT_PACKED
#if LIDR_REDUCE_MAX
    gl_FragColor = lidrPackDepthUnits(range.y);
#else
    gl_FragColor = lidrPackDepthUnits(range.x);
#endif
#else
#if LIDR_INPUT_PACKED
    range *= 1.0 / kLidrDepthUnits;
#endif
    gl_FragColor = vec4(range, 0.0, 1.0);
#endif
}
