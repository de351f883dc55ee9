// The MSAA pre-pass's per-sample distances as DepthSpanPass::writeCentreDepth packs them, four samples a texel:
// uLidrSampleDistances0 holds samples 0-3, uLidrSampleDistances1 samples 4-7 (with over four). The includer
// defines LIDR_SAMPLE_DISTANCE_COUNT (the sample count, at most 8); GLSL 1.50 (texelFetch).
// lidrSampleDistances(pixel, i) (i a constant after unrolling): sample i's view distance of the point its fragment
// shades, at the pixel centre; 0 where no surface covers it.
uniform sampler2D uLidrSampleDistances0;
#if LIDR_SAMPLE_DISTANCE_COUNT > 4
uniform sampler2D uLidrSampleDistances1;
#endif

struct LidrSampleDistances {
    vec4 first;   // samples 0-3
    vec4 second;  // samples 4-7 (0 with four or fewer)
};

LidrSampleDistances lidrReadSampleDistances(ivec2 pixel) {
    LidrSampleDistances d;
    d.first = texelFetch(uLidrSampleDistances0, pixel, 0);
#if LIDR_SAMPLE_DISTANCE_COUNT > 4
    d.second = texelFetch(uLidrSampleDistances1, pixel, 0);
#else
    d.second = vec4(0.0);
#endif
    return d;
}

float lidrSampleDistance(LidrSampleDistances d, int i) {
    return i < 4 ? d.first[i] : d.second[i - 4];
}
