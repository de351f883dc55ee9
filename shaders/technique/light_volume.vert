#version 120
// A light volume: the unit circumscribed sphere mesh scaled to the light's radius. It encloses the true
// sphere, so every pixel whose surface lies inside the light is covered.
attribute vec3 aPosition;
uniform mat4 uViewProj;
uniform vec4 uLightPosRadius;
// 1.0 where the context has no depth clamp and the volume reaches past the far plane: vertices beyond it are
// pulled onto it (x, y and w untouched, so the footprint is unchanged) instead of being clipped away; the
// pass then draws such a light without a depth test (conservative).
uniform float uClampToFar;

void main() {
    gl_Position = uViewProj * vec4(uLightPosRadius.xyz + aPosition * uLightPosRadius.w, 1.0);
    if (uClampToFar > 0.5 && gl_Position.w > 0.0) gl_Position.z = min(gl_Position.z, gl_Position.w);
}
