#version 120
// A light volume: the unit circumscribed sphere mesh scaled to the light's radius. It encloses the true
// sphere, so every pixel whose surface lies inside the light is covered.
attribute vec3 aPosition;
uniform mat4 uViewProj;
uniform vec4 uLightPosRadius;

void main() {
    gl_Position = uViewProj * vec4(uLightPosRadius.xyz + aPosition * uLightPosRadius.w, 1.0);
}
