#version 120
// Writes the light's packed index value to each bound index target; the fixed-function blender does the
// packing. LIDR_DRAW_TARGETS (1..4) targets are written at once through draw buffers.
#include "lidr_depth.glsl"
uniform vec4 uIndexColor[LIDR_DRAW_TARGETS];

void main() {
    lidrWriteDepth();
    for (int i = 0; i < LIDR_DRAW_TARGETS; ++i) gl_FragData[i] = uIndexColor[i];
}
