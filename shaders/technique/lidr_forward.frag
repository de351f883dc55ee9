#version 120
// LIDR forward pass: unpack this pixel's light indices and shade with those lights only.
// "lidr_unpack.glsl" is replaced by the packing scheme's unpack file (unpack_<scheme>.glsl); it defines
// LIDR_SLOTS, lidrUnpackBegin(uv) and lidrUnpackNext() (the index as its two bytes (low, high), (0, 0) for an
// empty slot; never one float, which fp16 fragments cannot hold above 2048), and LIDR_NULL_ENDS_LIST when the
// first empty slot means no more lights follow.
// Index targets are read through these two, so the per-sample MSAA path can swap in sampler2DMS and
// texelFetch(..., gl_SampleID) (lidr/technique/forward_pass.cpp) without touching the unpack files.
#ifndef LIDR_INDEX_SAMPLER
#define LIDR_INDEX_SAMPLER sampler2D
#define LIDR_FETCH_INDEX(s, uv) texture2D(s, uv)
#endif
#include "light_table.glsl"
#include "shading.glsl"
#include "lidr_unpack.glsl"

uniform vec2 uInvViewportSize;

void main() {
    LidrSurface s = lidrSurface();
    vec3 color = lidrAmbient(s);
    lidrUnpackBegin(gl_FragCoord.xy * uInvViewportSize);  // pixel centre -> index texel centre
    for (int slot = 0; slot < LIDR_SLOTS; ++slot) {
        vec2 index = lidrUnpackNext();  // (low byte, high byte)
        if (index.x + index.y < 0.5) {
#ifdef LIDR_NULL_ENDS_LIST
            break;
#else
            continue;
#endif
        }
        vec4 posRadius;
        vec3 lightColor;
        lidrFetchLight(index, posRadius, lightColor);
        color += lidrShadeLight(s, posRadius, lightColor);
    }
    gl_FragColor = vec4(color, uMaterialOpacity);
}
