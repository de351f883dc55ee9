#version 120
// The output transform applied to a finished linear frame: for modes that sum light in the framebuffer
// (multi-pass forward's additive blending), where no single shader sees a pixel's whole sum.
#include "output_transform.glsl"
uniform sampler2D uFrame;
varying vec2 vTexCoord;

void main() {
    vec4 linearColor = texture2D(uFrame, vTexCoord);
    gl_FragColor = lidrOutput(linearColor.rgb, linearColor.a);
}
