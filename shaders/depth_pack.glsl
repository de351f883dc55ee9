// Depth in colour targets for the tile min/max reduction (lidr/tile_depth_bounds.h).
// Float path (ARB_texture_float): RGBA32F, R = min and G = max window depth in [0, 1].
// Packed path (LIDR_DEPTH_PACKED, no float render targets): RGBA8, one 24-bit integer depth in RGB (R high),
// in units of 1 / (2^24 - 1); the min and the max are reduced in two chains. Values stay integers below 2^24
// in the shader, so the reduction itself is exact in fp32; only the first conversion rounds (by <= 1 unit).
#ifdef LIDR_DEPTH_PACKED
const float kLidrDepthUnits = 16777215.0;

vec4 lidrPackDepthUnits(float v) {
    float high = floor(v * (1.0 / 65536.0));
    v -= high * 65536.0;
    float mid = floor(v * (1.0 / 256.0));
    float low = v - mid * 256.0;
    return vec4(high, mid, low, 255.0) * (1.0 / 255.0);
}

float lidrUnpackDepthUnits(vec4 c) {
    return dot(floor(c.rgb * 255.0 + 0.5), vec3(65536.0, 256.0, 1.0));
}
#endif
