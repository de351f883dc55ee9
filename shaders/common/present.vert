#version 120
// presentFrame (lidr/render/present.h): one triangle over the caller's viewport, texture coordinates with it.
attribute vec3 aPosition;
varying vec2 vTexCoord;

void main() {
    vTexCoord = aPosition.xy * 0.5 + 0.5;
    gl_Position = vec4(aPosition.xy, 0.0, 1.0);
}
