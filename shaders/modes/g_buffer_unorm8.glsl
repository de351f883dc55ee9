// The RGBA8 G-buffer (GBufferFormat::Unorm8, lidr/modes/g_buffer_unorm8.h), for contexts without float colour
// buffers (OpenGL ES 2.0 / WebGL 1 without EXT_color_buffer_half_float). Included by g_buffer.glsl where
// LIDR_GBUFFER_UNORM8 is defined, in place of its float lidrGBufferSurface. Five RGBA8 targets, 20 bytes a pixel:
//   target 0: sqrt(albedo) rgb, sqrt(GGX alpha) (= roughness)
//   target 1: sqrt(F0) rgb, F90
//   target 2: the shading normal, octahedral at 12 + 12 bits over rgb, occlusion
//   target 3: the window depth as a 24-bit integer in rgb (R high), a = 1 where a surface was written
//   target 4: emission with a shared exponent: rgb = emission / 2^e (max channel in (0.5, 1]), a = (e + 128) / 255
// The square roots spend the 8 bits where the BRDF is sensitive (a dielectric's F0 of 0.04 is byte 51, not 10; dark
// albedo; smooth GGX lobes). Everything stays integer-valued below 2^24 in the shader: exact at fp32 (highp).
uniform sampler2D uGBuffer4;

const float kLidrGBuffer8Depth = 16777215.0;  // 2^24 - 1

vec3 lidrGBuffer8Octahedral(vec3 n) {  // two 12-bit values over three bytes
    vec2 u = floor(clamp(lidrOctahedralEncode(n) * 0.5 + 0.5, 0.0, 1.0) * 4095.0 + 0.5);
    float xHigh = floor(u.x * (1.0 / 16.0));
    float yHigh = floor(u.y * (1.0 / 256.0));
    return vec3(xHigh, (u.x - xHigh * 16.0) * 16.0 + yHigh, u.y - yHigh * 256.0) * (1.0 / 255.0);
}

vec3 lidrGBuffer8Normal(vec3 c) {
    vec3 b = floor(c * 255.0 + 0.5);
    float gHigh = floor(b.g * (1.0 / 16.0));
    vec2 u = vec2(b.r * 16.0 + gHigh, (b.g - gHigh * 16.0) * 256.0 + b.b);
    return lidrOctahedralDecode(u * (2.0 / 4095.0) - 1.0);
}

vec3 lidrGBuffer8Depth(float d) {
    float v = floor(clamp(d, 0.0, 1.0) * kLidrGBuffer8Depth + 0.5);
    float high = floor(v * (1.0 / 65536.0));
    v -= high * 65536.0;
    float mid = floor(v * (1.0 / 256.0));
    return vec3(high, mid, v - mid * 256.0) * (1.0 / 255.0);
}

vec4 lidrGBuffer8SharedExponent(vec3 c) {
    float m = max(max(c.r, c.g), c.b);
    if (m < 1.0e-6) return vec4(0.0);
    float e = ceil(log2(m));
    vec3 mantissa = c / exp2(e);
    if (max(max(mantissa.r, mantissa.g), mantissa.b) > 1.0) {  // log2 rounded down across a power of two
        e += 1.0;
        mantissa *= 0.5;
    }
    return vec4(mantissa, (e + 128.0) * (1.0 / 255.0));
}

vec3 lidrGBuffer8Emission(vec4 t) {
    return t.rgb * exp2(floor(t.a * 255.0 + 0.5) - 128.0);
}

// The surface at this pixel from the G-buffer; false where the pixel has none (the background).
bool lidrGBufferSurface(out LidrSurface s) {
    vec2 uv = gl_FragCoord.xy * uGBufferInvSize;
    vec4 t3 = texture2D(uGBuffer3, uv);
    if (t3.a < 0.5) return false;
    vec4 t0 = texture2D(uGBuffer0, uv);
    vec4 t1 = texture2D(uGBuffer1, uv);
    vec4 t2 = texture2D(uGBuffer2, uv);
    float depth = dot(floor(t3.rgb * 255.0 + 0.5), vec3(65536.0, 256.0, 1.0)) * (1.0 / kLidrGBuffer8Depth);
    vec4 world = uInverseViewProj * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    s.position = world.xyz / world.w;
    s.normal = lidrGBuffer8Normal(t2.rgb);
    s.toEye = normalize(uEyePosition - s.position);
    s.albedo = t0.rgb * t0.rgb;
    s.alpha = max(t0.a * t0.a, 0.01);
    s.f0 = t1.rgb * t1.rgb;
#ifdef LIDR_DIELECTRIC_SPECULAR
    s.f90 = t1.a;
#endif
    s.emission = lidrGBuffer8Emission(texture2D(uGBuffer4, uv));
    s.occlusion = t2.a;
    return true;
}
