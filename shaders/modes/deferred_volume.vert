#version 120
// A light's volume for deferred shading: the circumscribed sphere mesh (lidr::makeLightVolumeMesh) scaled to the
// light's radius; a spot light the cone mesh (lidr::makeSpotVolumeMesh) around its axis, placed as LIDR's
// light_volume.vert places it (lidr::spotVolumeVertex on the CPU). Vertices past
// the far plane are pulled onto it (x, y and w kept, so the footprint is unchanged): the back faces then still
// pass the depth test behind every surface. The scene's varyings are written (unused) as deferred_fullscreen.vert.
attribute vec3 aPosition;
uniform mat4 uViewProj;
uniform vec4 uVolumePosRadius;  // centre (apex), radius (a spot: the range x the cap's scale)
uniform vec4 uSpotVolume;       // a spot light: unit axis, the rim's polar angle; w = 0: a point light's sphere
varying vec3 vWorldPos;
varying vec3 vNormal;
varying vec2 vTexCoord;

vec3 spotVolumeVertex() {
    if (aPosition.z < 0.0) return vec3(0.0);
    vec3 axis = uSpotVolume.xyz;
    vec3 u = normalize(cross(axis, abs(axis.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 v = cross(axis, u);
    float polar = aPosition.z * uSpotVolume.w;
    return sin(polar) * (aPosition.x * u + aPosition.y * v) + cos(polar) * axis;
}

void main() {
    vWorldPos = vec3(0.0);
    vNormal = vec3(0.0, 0.0, 1.0);
    vTexCoord = vec2(0.0);
    vec3 unit = uSpotVolume.w > 0.0 ? spotVolumeVertex() : aPosition;
    gl_Position = uViewProj * vec4(uVolumePosRadius.xyz + unit * uVolumePosRadius.w, 1.0);
    if (gl_Position.w > 0.0) gl_Position.z = min(gl_Position.z, gl_Position.w);
}
