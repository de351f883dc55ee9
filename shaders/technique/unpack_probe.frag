#version 120
// Shader-unpack probe (tests): runs the scheme's real unpack ("lidr_unpack.glsl" substituted exactly as in the
// forward pass) at each pixel and writes what slots uSlotBase and uSlotBase + 1 returned, as 16-bit values
// (low byte, high byte, low byte, high byte). Every slot is unpacked, past the first null too, so the raw
// sequence can be compared with the CPU model.
#define LIDR_INDEX_SAMPLER sampler2D
#define LIDR_FETCH_INDEX(s, uv) texture2D(s, uv)
#include "lidr_unpack.glsl"

uniform vec2 uInvTargetSize;
uniform float uSlotBase;

void main() {
    lidrUnpackBegin(gl_FragCoord.xy * uInvTargetSize);
    vec2 first = vec2(0.0), second = vec2(0.0);  // (low byte, high byte) of slots uSlotBase and uSlotBase + 1
    for (int slot = 0; slot < LIDR_SLOTS; ++slot) {
        vec2 index = lidrUnpackNext();
        if (abs(float(slot) - uSlotBase) < 0.5) first = index;
        if (abs(float(slot) - uSlotBase - 1.0) < 0.5) second = index;
    }
    gl_FragColor = vec4(first, second) * (1.0 / 255.0);
}
