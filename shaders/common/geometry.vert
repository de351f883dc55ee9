#version 120
// Scene geometry for every pass that draws it (depth pre-pass, LIDR forward, reference, tiled...). The same
// source and `invariant` keep the depth of the pre-pass and of later EQUAL-tested passes bit-identical.
// A material's shader variant (lidr/render/material_variants.h) adds the second texture coordinate set and the
// tangent only where it reads them.
attribute vec3 aPosition;
attribute vec3 aNormal;
attribute vec2 aTexCoord;
#ifdef LIDR_TEXCOORD1
attribute vec2 aTexCoord1;
varying vec2 vTexCoord1;
#endif
#ifdef LIDR_NORMAL_TEXTURE
attribute vec4 aTangent;  // xyz along +u, w = +-1: the bitangent's side
varying vec4 vTangent;
#endif

uniform mat4 uViewProj;
uniform mat4 uModel;         // object -> world (identity for a Scene's meshes, whose positions are world space)
uniform mat3 uNormalMatrix;  // inverse transpose of uModel's upper 3x3

varying vec3 vWorldPos;
varying vec3 vNormal;
varying vec2 vTexCoord;

invariant gl_Position;

void main() {
    vWorldPos = (uModel * vec4(aPosition, 1.0)).xyz;
    vNormal = uNormalMatrix * aNormal;
    vTexCoord = aTexCoord;
#ifdef LIDR_TEXCOORD1
    vTexCoord1 = aTexCoord1;
#endif
#ifdef LIDR_NORMAL_TEXTURE
    vTangent = vec4((uModel * vec4(aTangent.xyz, 0.0)).xyz, aTangent.w);  // follows the surface, not its normal
#endif
    gl_Position = uViewProj * vec4(vWorldPos, 1.0);
}
