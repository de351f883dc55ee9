#version 120
// A light volume: the unit circumscribed sphere mesh scaled to the light's radius. It encloses the true
// sphere, so every pixel whose surface lies inside the light is covered. A spot light draws the cone mesh
// (lidr::makeSpotVolumeMesh: a vertex is (cos a, sin a, f), f the polar angle as a fraction of the rim's, f < 0
// the apex) around its axis, which encloses its range-capped cone (lidr::spotVolumeVertex is this on the CPU).
attribute vec3 aPosition;
uniform mat4 uViewProj;
uniform vec4 uLightPosRadius;  // centre (apex), radius (a spot: the range x the cap's scale)
uniform vec4 uSpotVolume;      // a spot light: unit axis, the rim's polar angle; w = 0: a point light's sphere
// 1.0 where the context has no depth clamp and the volume reaches past the far plane: vertices beyond it are
// pulled onto it (x, y and w untouched, so the footprint is unchanged) instead of being clipped away; the
// pass then draws such a light without a depth test (conservative).
uniform float uClampToFar;

vec3 spotVolumeVertex() {
    if (aPosition.z < 0.0) return vec3(0.0);
    vec3 axis = uSpotVolume.xyz;
    vec3 u = normalize(cross(axis, abs(axis.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 v = cross(axis, u);  // (u, v, axis) right-handed: the mesh's winding is kept
    float polar = aPosition.z * uSpotVolume.w;
    return sin(polar) * (aPosition.x * u + aPosition.y * v) + cos(polar) * axis;
}

void main() {
    vec3 unit = uSpotVolume.w > 0.0 ? spotVolumeVertex() : aPosition;
    gl_Position = uViewProj * vec4(uLightPosRadius.xyz + unit * uLightPosRadius.w, 1.0);
    if (uClampToFar > 0.5 && gl_Position.w > 0.0) gl_Position.z = min(gl_Position.z, gl_Position.w);
}
