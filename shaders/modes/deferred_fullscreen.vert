#version 120
// One triangle covering the viewport for the deferred modes' full-screen passes. The scene's varyings are written
// (unused) because the passes include shading.glsl, whose material half declares them.
attribute vec3 aPosition;
uniform mat4 uViewProj;  // set with the shading uniforms; unused
varying vec3 vWorldPos;
varying vec3 vNormal;
varying vec2 vTexCoord;

void main() {
    vWorldPos = vec3(0.0);
    vNormal = vec3(0.0, 0.0, 1.0);
    vTexCoord = vec2(0.0);
    gl_Position = vec4(aPosition.xy, 0.0, 1.0);
}
