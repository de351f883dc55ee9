// Depth in colour targets for the tile min/max reduction (lidr/modes/tile_depth_bounds.h). GL 2.1 cannot sample
// the packed depth-stencil renderbuffer, so the pre-Z pass also writes each fragment's depth here.
// Packed: an RGBA8 texel holds one depth as a 24-bit integer in RGB (R high), in units of 1 / (2^24 - 1).
// The values stay integers below 2^24 in the shader, so min/max over them is exact in fp32; only the first
// conversion (pre-Z) rounds, by at most one unit.
// Float (ARB_texture_float render targets): an RGBA32F texel holds R = min and G = max window depth.
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
