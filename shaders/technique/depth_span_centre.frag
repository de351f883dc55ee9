#version 120
// DepthSpanPass::writeCentreDepth (sphere-span with the samples' distances): sample 0's shaded point as the pixel's
// single-sample depth, the "centre" surface the sphere tests, the tiles and the evaluation read, written by one
// full-screen pass instead of a second geometry pass; the far plane (as cleared) where sample 0 has no surface.
// The samples' distances four a texel (targets 2 and 3): the volume shader and the forward pass's hidden-fragment
// skip then read a pixel's samples with one fetch (two over four samples) instead of one per sample.
// LIDR_SPAN_RANGES (tile-culled frames, read back by DepthSpanPass::readDepthRanges): targets 0 and 1, per pixel
// the nearest and farthest window depth of the points its samples shade, each widened as the volume shader widens it
// (1/4096 of its distance), so the tiles hold whatever that test keeps; (1, 1) where the pixel has none.
// LIDR_SPAN_SAMPLES: the sample count (at most 8). Compiled as GLSL 1.50 (perSampleGlsl150).
uniform sampler2DMS uSampleDistances;  // per sample, the view distance of the point it shades (0: none)
uniform vec2 uDepthToDistance;         // window depth d -> view distance x / (d + y); so d = x / distance - y

float lidrWindowDepth(float distance) {
    return clamp(uDepthToDistance.x / distance - uDepthToDistance.y, 0.0, 1.0);
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 byTexel[2] = vec4[2](vec4(0.0), vec4(0.0));
    // The nearest and farthest distance first (depth falls with 1 / distance), then two conversions.
    float nearest = 1e30, farthest = 0.0;
    for (int i = 0; i < LIDR_SPAN_SAMPLES; ++i) {  // a constant: unrolled (llvmpipe: 10 -> 7 ms at 1024x768 4x)
        float x = texelFetch(uSampleDistances, texel, i).r;
        byTexel[i / 4][i - 4 * (i / 4)] = x;
        nearest = x > 0.0 ? min(nearest, x) : nearest;
        farthest = max(farthest, x);
    }
    gl_FragDepth = byTexel[0].x > 0.0 ? lidrWindowDepth(byTexel[0].x) : 1.0;
#ifdef LIDR_SPAN_RANGES
    bool none = farthest <= 0.0;
    gl_FragData[0] = vec4(none ? 1.0 : lidrWindowDepth(nearest * (1.0 - 1.0 / 4096.0)));
    gl_FragData[1] = vec4(none ? 1.0 : lidrWindowDepth(farthest * (1.0 + 1.0 / 4096.0)));
#endif
    gl_FragData[2] = byTexel[0];
#if LIDR_SPAN_SAMPLES > 4
    gl_FragData[3] = byTexel[1];
#endif
}
