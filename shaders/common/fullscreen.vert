#version 120
// One triangle covering the viewport, for screen-space passes (the tile depth reduction).
attribute vec3 aPosition;

void main() {
    gl_Position = vec4(aPosition.xy, 0.0, 1.0);
}
