// The frame's output transform, the last step of every mode's shading: linear light scaled by the exposure
// (in stops, 0 = x1), tone-mapped by a named operator, encoded to sRGB for 8-bit targets, PNGs and windows.
// Each uniform's zero is the identity, so a program that never sets them writes linear values as before.
// The CPU model of the same steps is lidr/render/output_transform.h; keep the two together.
uniform float uExposureStops;
uniform float uToneMap;    // 0: none (clamped), 1: Khronos PBR Neutral, 2: ACES filmic (Hill's fit of RRT + ODT)
uniform float uSrgbOutput; // 1: sRGB-encode, 0: write linear

// Khronos PBR Neutral (github.com/KhronosGroup/ToneMapping, PBR_Neutral): identity below 0.76 apart from a small
// black-level offset, so base colours under moderate light come out as authored; highlights compress to 1.
vec3 lidrToneMapPbrNeutral(vec3 color) {
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < 0.76) return color;
    float d = 1.0 - 0.76;
    float newPeak = 1.0 - d * d / (peak + d - 0.76);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (0.15 * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

// ACES filmic, Stephen Hill's fit: sRGB -> ACES AP1-ish input matrix, the RRT + ODT rational fit, back.
vec3 lidrToneMapAcesFitted(vec3 color) {
    vec3 v = vec3(dot(vec3(0.59719, 0.35458, 0.04823), color), dot(vec3(0.07600, 0.90834, 0.01566), color),
                  dot(vec3(0.02840, 0.13383, 0.83777), color));
    vec3 a = v * (v + 0.0245786) - 0.000090537;
    vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    v = a / b;
    return vec3(dot(vec3(1.60475, -0.53108, -0.07367), v), dot(vec3(-0.10208, 1.10813, -0.00605), v),
                dot(vec3(-0.00327, -0.07276, 1.07602), v));
}

vec3 lidrLinearToSrgb(vec3 c) {
    vec3 low = c * 12.92;
    vec3 high = 1.055 * pow(max(c, vec3(0.0031308)), vec3(1.0 / 2.4)) - 0.055;
    return mix(low, high, step(vec3(0.0031308), c));
}

vec3 lidrSrgbToLinear(vec3 c) {
    vec3 low = c * (1.0 / 12.92);
    vec3 high = pow((max(c, vec3(0.04045)) + 0.055) * (1.0 / 1.055), vec3(2.4));
    return mix(low, high, step(vec3(0.04045), c));
}

vec4 lidrOutput(vec3 linearColor, float alpha) {
    vec3 c = max(linearColor * exp2(uExposureStops), vec3(0.0));
#ifdef LIDR_TONE_MAP  // the frame's shading variant (lidr/render/shading_variants.h): operator and encoding compiled in
#if LIDR_TONE_MAP == 2
    c = lidrToneMapAcesFitted(c);
#elif LIDR_TONE_MAP == 1
    c = lidrToneMapPbrNeutral(c);
#endif
    c = clamp(c, 0.0, 1.0);
#if LIDR_SRGB_OUTPUT
    c = lidrLinearToSrgb(c);
#endif
#else  // uniform branches: a SIMD rasteriser runs both operators under masks
    if (uToneMap > 1.5) c = lidrToneMapAcesFitted(c);
    else if (uToneMap > 0.5) c = lidrToneMapPbrNeutral(c);
    c = clamp(c, 0.0, 1.0);
    if (uSrgbOutput > 0.5) c = lidrLinearToSrgb(c);
#endif
    return vec4(c, alpha);
}
