#version 120
// A light's volume for deferred shading: the circumscribed sphere mesh (lidr::makeLightVolumeMesh) scaled to the
// light's radius; a spot light draws its sphere too (the shading's cone term is 0 outside the cone). Vertices past
// the far plane are pulled onto it (x, y and w kept, so the footprint is unchanged): the back faces then still
// pass the depth test behind every surface. The scene's varyings are written (unused) as deferred_fullscreen.vert.
attribute vec3 aPosition;
uniform mat4 uViewProj;
uniform vec4 uVolumePosRadius;
varying vec3 vWorldPos;
varying vec3 vNormal;
varying vec2 vTexCoord;

void main() {
    vWorldPos = vec3(0.0);
    vNormal = vec3(0.0, 0.0, 1.0);
    vTexCoord = vec2(0.0);
    gl_Position = uViewProj * vec4(uVolumePosRadius.xyz + aPosition * uVolumePosRadius.w, 1.0);
    if (gl_Position.w > 0.0) gl_Position.z = min(gl_Position.z, gl_Position.w);
}
