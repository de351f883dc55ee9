// The material side of lidr's shading, shared by shading.glsl and the depth pre-pass (depth_only.frag, whose
// MASK variant cuts out what the shading passes cut out): the material uniforms, the varyings of geometry.vert
// and the per-pixel textures. Needs output_transform.glsl (lidrSrgbToLinear) included before it.
uniform vec3 uMaterialDiffuse;   // the base colour factor (linear)
uniform float uMaterialMetallic;
uniform float uMaterialRoughness;  // perceptual roughness; alpha = roughness^2
uniform float uMaterialOpacity;
uniform vec3 uMaterialEmissive;
uniform float uMaterialHasTexture;  // 1 where the base colour texture is bound (for material shaders of programs)
uniform sampler2D uMaterialTexture;  // the base colour texture

varying vec3 vWorldPos;
varying vec3 vNormal;
varying vec2 vTexCoord;

// Per-pixel material textures come in shader variants (lidr/render/material_variants.h): a material's program is
// compiled with LIDR_<NAME>_TEXTURE defined for each texture it has, LIDR_<NAME>_UV 1 where that texture reads the
// second coordinate set, so a material without textures (the room) runs the code it always ran. Each texture's
// coordinates go through its KHR_texture_transform matrix.
#ifdef LIDR_TEXCOORD1
varying vec2 vTexCoord1;
#define LIDR_UV(set) ((set) == 1 ? vTexCoord1 : vTexCoord)
#else
#define LIDR_UV(set) vTexCoord
#endif
#define LIDR_TRANSFORMED_UV(transform, set) ((transform) * vec3(LIDR_UV(set), 1.0)).xy

#ifdef LIDR_BASE_COLOR_TEXTURE
uniform mat3 uBaseColorUvTransform;
#endif
// KHR_materials_ior / KHR_materials_specular (lidr::DielectricSpecular): the dielectric's F0 and F90 instead of
// glTF's 0.04 and 1, only in the variant of a material that has them.
#ifdef LIDR_DIELECTRIC_SPECULAR
uniform vec3 uMaterialDielectricF0;
uniform float uMaterialDielectricF90;
#endif
#ifdef LIDR_EMISSIVE_TEXTURE
uniform sampler2D uEmissiveTexture;
uniform mat3 uEmissiveUvTransform;
#endif
#ifdef LIDR_METALLIC_ROUGHNESS_TEXTURE
uniform sampler2D uMetallicRoughnessTexture;
uniform mat3 uMetallicRoughnessUvTransform;
#endif
#ifdef LIDR_OCCLUSION_TEXTURE
uniform sampler2D uOcclusionTexture;
uniform mat3 uOcclusionUvTransform;
uniform float uOcclusionStrength;
#endif
#ifdef LIDR_NORMAL_TEXTURE
uniform sampler2D uNormalTexture;
uniform mat3 uNormalUvTransform;
uniform float uNormalScale;
varying vec4 vTangent;
#endif

// Colour textures (base colour, emissive) hold sRGB-encoded texels. Desktop GL (2.1 has sRGB textures in core)
// uploads them as SRGB8_ALPHA8 and the texture unit decodes, before filtering; OpenGL ES 2.0 / WebGL 1 have no
// sRGB texture format without an extension, so the texel is decoded here, after filtering
// (lidr/render/gpu_scene.cpp). Data textures (metallic-roughness, occlusion, normal) are linear.
vec4 lidrColorTexel(sampler2D map, vec2 uv) {
    vec4 texel = texture2D(map, uv);
#if defined(GL_ES) || defined(LIDR_SRGB_DECODE_IN_SHADER)
    texel.rgb = lidrSrgbToLinear(texel.rgb);
#endif
    return texel;
}

// The base colour's RGBA: factor x texel (the alpha is the base colour texture's, for MASK materials).
vec4 lidrBaseColor() {
    vec4 base = vec4(uMaterialDiffuse, uMaterialOpacity);
#ifdef LIDR_BASE_COLOR_TEXTURE
    base *= lidrColorTexel(uMaterialTexture, LIDR_TRANSFORMED_UV(uBaseColorUvTransform, LIDR_BASE_COLOR_UV));
#endif
    return base;
}

// alphaMode MASK (glTF): the fragment is not there where the base colour's alpha is below the cutoff, in the
// depth pre-pass as in the shading passes, so LIDR's light lists and the image agree on the cut-out.
#ifdef LIDR_ALPHA_MASK
uniform float uAlphaCutoff;
#endif
void lidrAlphaTest(float alpha) {
#ifdef LIDR_ALPHA_MASK
    if (alpha < uAlphaCutoff) discard;
#endif
}
