// The one shading function of lidr: Blinn-Phong with attenuation saturate(1 - d^2 / r^2), in linear light.
// LIDR, tiled, forward and the brute-force reference all call it, so their images differ only by which lights
// they sum; each ends with lidrOutput (output_transform.glsl), multi-pass forward once over its finished sum.
#include "output_transform.glsl"
uniform vec3 uEyePosition;
uniform vec3 uAmbient;
uniform vec3 uMaterialDiffuse;
uniform vec3 uMaterialSpecular;
uniform float uMaterialShininess;
uniform float uMaterialOpacity;
uniform vec3 uMaterialEmissive;
uniform float uMaterialHasTexture;
uniform sampler2D uMaterialTexture;

varying vec3 vWorldPos;
varying vec3 vNormal;
varying vec2 vTexCoord;

// Base-colour textures hold sRGB-encoded texels. Desktop GL (2.1 has sRGB textures in core) uploads them as
// SRGB8_ALPHA8 and the texture unit decodes, before filtering; OpenGL ES 2.0 / WebGL 1 have no sRGB texture
// format without an extension, so the texel is decoded here, after filtering (lidr/render/gpu_scene.cpp).
vec4 lidrBaseColorTexel(vec2 uv) {
    vec4 texel = texture2D(uMaterialTexture, uv);
#if defined(GL_ES) || defined(LIDR_SRGB_DECODE_IN_SHADER)
    texel.rgb = lidrSrgbToLinear(texel.rgb);
#endif
    return texel;
}

struct LidrSurface {
    vec3 position;
    vec3 normal;
    vec3 toEye;
    vec3 albedo;
};

LidrSurface lidrSurface() {
    LidrSurface s;
    s.position = vWorldPos;
    s.normal = normalize(vNormal);
    if (!gl_FrontFacing) s.normal = -s.normal;  // two-sided: the back of a wall is lit from its own side
    s.toEye = normalize(uEyePosition - vWorldPos);
    s.albedo = uMaterialDiffuse;
    if (uMaterialHasTexture > 0.5) s.albedo *= lidrBaseColorTexel(vTexCoord).rgb;
    return s;
}

// Ambient light plus the material's own emission: the light-independent term every mode adds once per pixel.
vec3 lidrAmbient(LidrSurface s) {
    return uAmbient * s.albedo + uMaterialEmissive;
}

vec3 lidrShadeLight(LidrSurface s, vec4 posRadius, vec3 lightColor) {
    vec3 toLight = posRadius.xyz - s.position;
    float d2 = dot(toLight, toLight);
    float r2 = posRadius.w * posRadius.w;
    float attenuation = clamp(1.0 - d2 / r2, 0.0, 1.0);
    if (attenuation <= 0.0) return vec3(0.0);
    vec3 L = toLight * inversesqrt(max(d2, 1e-12));
    float nDotL = max(dot(s.normal, L), 0.0);
    vec3 H = normalize(L + s.toEye);
    float specular = nDotL > 0.0 ? pow(max(dot(s.normal, H), 0.0), uMaterialShininess) : 0.0;
    return (s.albedo * nDotL + uMaterialSpecular * specular) * lightColor * attenuation;
}
