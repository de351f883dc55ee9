// The one shading function of lidr, in linear light: the glTF 2.0 metallic-roughness BRDF (the specification's
// appendix B: Lambert diffuse, GGX distribution, height-correlated Smith-GGX visibility, Schlick Fresnel with F0
// mixed by metallic) under point and spot lights, lidr's falloff or glTF's (lidrShadeLight). LIDR, tiled, forward
// and the brute-force reference all call it; each ends with lidrOutput (output_transform.glsl); CPU: eval/brdf.h.
#include "output_transform.glsl"
#define LIDR_PI 3.14159265358979
uniform vec3 uEyePosition;
uniform vec3 uAmbient;
#include "material.glsl"

struct LidrSurface {
    vec3 position;
    vec3 normal;
    vec3 toEye;
    vec3 albedo;     // the diffuse colour: base colour x (1 - metallic)
    vec3 f0;         // specular reflectance at normal incidence: mix(0.04, base colour, metallic)
#ifdef LIDR_DIELECTRIC_SPECULAR
    float f90;       // ... at grazing angles: mix(specular weight, 1, metallic) (1 without the extensions)
#endif
    float alpha;     // GGX alpha = roughness^2, at least 0.01 (a mirror has no lobe; alpha^2 stays normal in fp16)
    float occlusion; // of the ambient light only (glTF: occlusion applies to indirect light)
    vec3 emission;   // emissive factor x emissive texel
};

// The reflectance at grazing angles: the material's own with KHR_materials_ior / _specular, else glTF's 1.
#ifdef LIDR_DIELECTRIC_SPECULAR
#define lidrF90(s) (s).f90
#else
#define lidrF90(s) 1.0
#endif

// The shading normal: the interpolated normal, turned to the side the eye sees (a double-sided surface is lit
// from its own side), then bent by the normal texture in the tangent frame of the pixel.
vec3 lidrShadingNormal() {
    vec3 n = normalize(vNormal);
    float side = gl_FrontFacing ? 1.0 : -1.0;
    n *= side;
#ifdef LIDR_NORMAL_TEXTURE
    vec3 t = vTangent.xyz - n * dot(n, vTangent.xyz);  // Gram-Schmidt: interpolation bends the frame
    t = dot(t, t) > 1e-12 ? normalize(t) : vec3(0.0);
    vec3 b = cross(n, t) * (vTangent.w * side);
    vec3 m = texture2D(uNormalTexture, LIDR_TRANSFORMED_UV(uNormalUvTransform, LIDR_NORMAL_UV)).xyz * 2.0 - 1.0;
    m.xy *= uNormalScale;
    vec3 bent = t * m.x + b * m.y + n * m.z;
    n = dot(bent, bent) > 1e-12 ? normalize(bent) : n;
#endif
    return n;
}

LidrSurface lidrSurface() {
    LidrSurface s;
    s.position = vWorldPos;
    s.normal = lidrShadingNormal();
    s.toEye = normalize(uEyePosition - vWorldPos);
    vec4 baseColor = lidrBaseColor();
    lidrAlphaTest(baseColor.a);
    vec3 base = baseColor.rgb;
    float metallic = uMaterialMetallic;
    float roughness = uMaterialRoughness;
#ifdef LIDR_METALLIC_ROUGHNESS_TEXTURE
    vec4 mr = texture2D(uMetallicRoughnessTexture, LIDR_TRANSFORMED_UV(uMetallicRoughnessUvTransform, LIDR_METALLIC_ROUGHNESS_UV));
    roughness *= mr.g;
    metallic *= mr.b;
#endif
    s.albedo = base * (1.0 - metallic);
#ifdef LIDR_DIELECTRIC_SPECULAR
    s.f0 = mix(uMaterialDielectricF0, base, metallic);
    s.f90 = mix(uMaterialDielectricF90, 1.0, metallic);
#else
    s.f0 = mix(vec3(0.04), base, metallic);
#endif
    s.alpha = max(roughness * roughness, 0.01);
    s.occlusion = 1.0;
#ifdef LIDR_OCCLUSION_TEXTURE
    float ao = texture2D(uOcclusionTexture, LIDR_TRANSFORMED_UV(uOcclusionUvTransform, LIDR_OCCLUSION_UV)).r;
    s.occlusion = 1.0 + uOcclusionStrength * (ao - 1.0);
#endif
    s.emission = uMaterialEmissive;
#ifdef LIDR_EMISSIVE_TEXTURE
    s.emission *= lidrColorTexel(uEmissiveTexture, LIDR_TRANSFORMED_UV(uEmissiveUvTransform, LIDR_EMISSIVE_UV)).rgb;
#endif
    return s;
}

// The environment light (issue 39; lidr/scene/environment.h, lidr/render/environment_maps.h): radiance from
// every direction, an image. LIDR_ENVIRONMENT is the frame's shading variant (lidr/render/shading_variants.h):
// 0 none (the code that ran before environments), 1 the specular cube at an explicit LOD (textureCubeLod: desktop
// ARB_shader_texture_lod, ES EXT_shader_texture_lod), 2 at a mip bias over the implicit LOD (without those), 3 the
// diffuse term alone; LIDR_ENVIRONMENT_RGBM 1: RGBA8 storage (RGBM cube, 16-bit pairs in the table). A program
// drawn without a key (none of lidr's shading draws) reads uEnvironment instead and looks up with the bias.
#ifndef LIDR_ENVIRONMENT
#define LIDR_ENVIRONMENT_ON 1
#define LIDR_ENVIRONMENT_LOOKUP 2
#define LIDR_ENVIRONMENT_UNIFORMS 1
#elif LIDR_ENVIRONMENT > 0
#define LIDR_ENVIRONMENT_ON 1
#define LIDR_ENVIRONMENT_LOOKUP LIDR_ENVIRONMENT
#endif
#ifdef LIDR_ENVIRONMENT_ON
uniform vec3 uEnvironmentSh[9];  // E(n) / pi x intensity: c0 + c1 y + c2 z + c3 x + c4 xy + c5 yz + c6 (3z^2 - 1) + c7 xz + c8 (x^2 - y^2)
uniform vec4 uEnvironment;       // intensity, RGBM range (0: half floats), the LOD of roughness 1, split-sum table size
uniform samplerCube uEnvironmentSpecular;  // GGX-prefiltered radiance, roughness r at LOD r x uEnvironment.z
uniform float uEnvironmentSize;            // its level 0's texels a side
uniform sampler2D uEnvironmentSplitSum;    // (A, B) per (n.v, roughness) at texel centres

// The irradiance over pi (a white Lambert surface's light), from 9 spherical harmonics (lidr::irradianceOverPi).
vec3 lidrEnvironmentIrradiance(vec3 n) {
    vec3 e = uEnvironmentSh[0] + uEnvironmentSh[1] * n.y + uEnvironmentSh[2] * n.z + uEnvironmentSh[3] * n.x +
             uEnvironmentSh[4] * (n.x * n.y) + uEnvironmentSh[5] * (n.y * n.z) + uEnvironmentSh[6] * (3.0 * n.z * n.z - 1.0) +
             uEnvironmentSh[7] * (n.x * n.z) + uEnvironmentSh[8] * (n.x * n.x - n.y * n.y);
    return max(e, vec3(0.0));
}

#if LIDR_ENVIRONMENT_LOOKUP != 3
// Decoded after filtering, as the CPU model does (lidr::sampleStoredSpecular): RGBM's rgb x m x range.
vec3 lidrEnvironmentRadiance(vec4 texel) {
#ifndef LIDR_ENVIRONMENT_UNIFORMS
#if LIDR_ENVIRONMENT_RGBM
    return texel.rgb * (texel.a * uEnvironment.y);
#else
    return texel.rgb;
#endif
#else
    return uEnvironment.y > 0.0 ? texel.rgb * (texel.a * uEnvironment.y) : texel.rgb;
#endif
}

// The split sum's (A, B): the specular integral under the prefiltered light is radiance x (F0 A + B).
vec2 lidrEnvironmentSplitSum(float nDotV, float roughness) {
    vec2 uv = (vec2(nDotV, roughness) * (uEnvironment.w - 1.0) + 0.5) / uEnvironment.w;
    vec4 t = texture2D(uEnvironmentSplitSum, uv);
#ifndef LIDR_ENVIRONMENT_UNIFORMS
#if LIDR_ENVIRONMENT_RGBM
    return vec2(t.r * 256.0 + t.g, t.b * 256.0 + t.a) * (255.0 / 65535.0);
#else
    return t.rg;
#endif
#else
    return uEnvironment.y > 0.0 ? vec2(t.r * 256.0 + t.g, t.b * 256.0 + t.a) * (255.0 / 65535.0) : t.rg;
#endif
}
#endif

// Diffuse from the spherical harmonics, specular from the cube in the reflected direction at the roughness's LOD
// times the split sum (Karis 2013); the caller applies the occlusion.
vec3 lidrEnvironment(LidrSurface s, float nDotV, float roughness) {
    vec3 light = s.albedo * lidrEnvironmentIrradiance(s.normal);
#if LIDR_ENVIRONMENT_LOOKUP != 3
    vec3 r = reflect(-s.toEye, s.normal);
#if LIDR_ENVIRONMENT_LOOKUP == 1
    vec4 texel = textureCubeLod(uEnvironmentSpecular, r, roughness * uEnvironment.z);
#else
    // A bias over the implicit LOD GL takes from the pixel's derivatives: the roughness's LOD minus an estimate of
    // that implicit LOD, so the two add up to about the roughness's (where derivatives exist: desktop GLSL 1.20,
    // ES with OES_standard_derivatives; else the roughness's LOD as the bias alone, sharper where the reflection
    // changes slowly across pixels). The estimate: the reflection's change per pixel over twice its major axis
    // (a face's coordinates run over [-|ma|, |ma|]) in texels of level 0.
    float bias = roughness * uEnvironment.z;
#if !defined(GL_ES) || defined(GL_OES_standard_derivatives)
    vec3 dx = dFdx(r), dy = dFdy(r);
    float major = max(abs(r.x), max(abs(r.y), abs(r.z)));
    float footprint = sqrt(max(dot(dx, dx), dot(dy, dy))) * uEnvironmentSize * 0.5 / major;
    bias -= log2(max(footprint, 1e-6));
#endif
    vec4 texel = textureCube(uEnvironmentSpecular, r, bias);
#endif
    vec2 ab = lidrEnvironmentSplitSum(nDotV, roughness);
    light += lidrEnvironmentRadiance(texel) * (s.f0 * ab.x + lidrF90(s) * ab.y) * uEnvironment.x;
#endif
    return light;
}
#endif

// Ambient light (darkened by the occlusion texture) plus the material's own emission: the light-independent term every mode adds once per pixel.
// The ambient is uniform radiance from every direction: the diffuse part integrates to ambient x albedo, the
// specular part to ambient x (F0 A + F90 B), Karis' analytic fit of the split-sum environment BRDF. The
// environment light, where the frame has one, adds to it (and is darkened by the occlusion too).
vec3 lidrAmbient(LidrSurface s) {
    float nDotV = clamp(dot(s.normal, s.toEye), 0.0, 1.0);
    float roughness = sqrt(s.alpha);
    vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
    float a004 = min(r.x * r.x, exp2(-9.28 * nDotV)) * r.x + r.y;
    vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
    vec3 light = uAmbient * (s.albedo + s.f0 * ab.x + lidrF90(s) * ab.y);
#ifdef LIDR_ENVIRONMENT_ON
    light += lidrEnvironment(s, nDotV, roughness);
#endif
    return light * s.occlusion + s.emission;
}

// Light arriving from direction L (unit, towards the light) with colour x attenuation: BRDF x pi x colour x
// attenuation x n.l. The pi makes a light's colour what it gives a white Lambert surface facing it at its centre
// (as lidr's lights did before the BRDF had its 1/pi; doc/colour.md). Every light type ends here.
vec3 lidrShadeIncoming(LidrSurface s, vec3 L, float attenuation, vec3 lightColor) {
    float nDotL = dot(s.normal, L);
    if (nDotL <= 0.0) return vec3(0.0);
    vec3 H = normalize(L + s.toEye);
    float nDotV = max(dot(s.normal, s.toEye), 1e-4);
    float nDotH = max(dot(s.normal, H), 0.0);
    float vDotH = clamp(dot(s.toEye, H), 0.0, 1.0);  // above 1 by rounding (a light at the eye), pow() of a
                                                     // negative base would be undefined: speckled NaN pixels
    float a2 = s.alpha * s.alpha;
    float denom = nDotH * nDotH * (a2 - 1.0) + 1.0;
    float D = a2 / (LIDR_PI * denom * denom);
    float visibility = 0.5 / (nDotL * sqrt(nDotV * nDotV * (1.0 - a2) + a2) + nDotV * sqrt(nDotL * nDotL * (1.0 - a2) + a2));
    float fresnelWeight = pow(1.0 - vDotH, 5.0);
#ifdef LIDR_DIELECTRIC_SPECULAR
    vec3 F = s.f0 + (s.f90 - s.f0) * fresnelWeight;  // KHR_materials_specular: F90 = the weight for a dielectric
#else
    vec3 F = s.f0 + (1.0 - s.f0) * fresnelWeight;
#endif
    vec3 brdf = (1.0 - F) * s.albedo * (1.0 / LIDR_PI) + F * (D * visibility);
    return brdf * (LIDR_PI * nDotL * attenuation) * lightColor;
}

// One point or spot light. posRadius.w > 0: lidr's falloff saturate(1 - d^2 / r^2) (scene files, built-in
// scenes); posRadius.w < 0: KHR_lights_punctual's inverse square with the specification's range window,
// saturate(1 - (d / r)^4) / max(d^2, 1e-4) with r = -w (glTF lights; the 1 cm floor keeps a surface at the light
// finite). Both are exactly 0 from d = r on, so r stays the light volume. The spot cone: spot = (axis x scale,
// offset) from the light table (lidr::spotCone), the term saturate(dot(-L, axis) x scale + offset)^2,
// KHR_lights_punctual's smooth falloff from the inner to the outer cone; a point light's (0, 0, 0, 1) makes it 1.
vec3 lidrShadeLight(LidrSurface s, vec4 posRadius, vec3 lightColor, vec4 spot) {
    vec3 toLight = posRadius.xyz - s.position;
    float d2 = dot(toLight, toLight);
    float r2 = posRadius.w * posRadius.w;
    float attenuation;
    if (posRadius.w > 0.0) {
        attenuation = clamp(1.0 - d2 / r2, 0.0, 1.0);
    } else {
        float q = d2 / r2;
        attenuation = clamp(1.0 - q * q, 0.0, 1.0) / max(d2, 1e-4);
    }
    if (attenuation <= 0.0) return vec3(0.0);
    vec3 L = toLight * inversesqrt(max(d2, 1e-12));
    float cone = clamp(spot.w - dot(L, spot.xyz), 0.0, 1.0);
    attenuation *= cone * cone;
    if (attenuation <= 0.0) return vec3(0.0);
    return lidrShadeIncoming(s, L, attenuation, lightColor);
}

// A point light (a material shader's own lights).
vec3 lidrShadeLight(LidrSurface s, vec4 posRadius, vec3 lightColor) {
    return lidrShadeLight(s, posRadius, lightColor, vec4(0.0, 0.0, 0.0, 1.0));
}

// Directional lights (the sun) touch every pixel, so they are not indexed: every mode adds this sum once per
// pixel, right after lidrAmbient, in its forward pass (the reference too), so the modes stay equal. lidr sets
// the uniforms from ShadingParameters::directionalLights (lidr/render/shading_pass.cpp): xyz towards the light,
// unit; the colour in rgb. At most LIDR_MAX_DIRECTIONAL_LIGHTS (lidr::maxDirectionalLights).
#define LIDR_MAX_DIRECTIONAL_LIGHTS 4
uniform vec4 uDirectionalLightToLight[LIDR_MAX_DIRECTIONAL_LIGHTS];
uniform vec4 uDirectionalLightColor[LIDR_MAX_DIRECTIONAL_LIGHTS];
uniform float uDirectionalLightCount;

// LIDR_DIRECTIONAL_LIGHTS (the frame's shading variant, lidr/render/shading_variants.h): the count compiled in, so
// a frame without a sun runs no code for it. A uniform count cannot do that on a SIMD rasteriser: the loop's body
// runs under a mask at least once (llvmpipe: a sixth of LIDR's forward pass on the hall, doc/benchmarks.md).
vec3 lidrDirectionalLights(LidrSurface s) {
    vec3 sum = vec3(0.0);
#ifdef LIDR_DIRECTIONAL_LIGHTS
    for (int i = 0; i < LIDR_DIRECTIONAL_LIGHTS; ++i)
        sum += lidrShadeIncoming(s, uDirectionalLightToLight[i].xyz, 1.0, uDirectionalLightColor[i].rgb);
#else
    for (int i = 0; i < LIDR_MAX_DIRECTIONAL_LIGHTS; ++i) {
        if (float(i) >= uDirectionalLightCount) break;
        sum += lidrShadeIncoming(s, uDirectionalLightToLight[i].xyz, 1.0, uDirectionalLightColor[i].rgb);
    }
#endif
    return sum;
}
