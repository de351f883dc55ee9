#version 120
// Scene geometry for every pass that draws it (depth pre-pass, LIDR forward, reference, tiled...). The same
// source and `invariant` keep the depth of the pre-pass and of later EQUAL-tested passes bit-identical.
attribute vec3 aPosition;
attribute vec3 aNormal;
attribute vec2 aTexCoord;

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
    gl_Position = uViewProj * vec4(vWorldPos, 1.0);
}
