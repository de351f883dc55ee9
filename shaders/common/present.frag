#version 120
// presentFrame: the finished frame, copied as it is (alpha too) into the caller's framebuffer.
uniform sampler2D uFrame;
varying vec2 vTexCoord;

void main() {
    gl_FragColor = texture2D(uFrame, vTexCoord);
}
