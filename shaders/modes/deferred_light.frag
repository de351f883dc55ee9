#version 120
// Deferred shading's light pass: one light's term at the G-buffer's surface, drawn over the light's volume and
// added by the blender (ONE, ONE) into the accumulation target. Alpha counts the lighting computations.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"
#include "g_buffer.glsl"

uniform float uLightIndex;
#ifndef LIDR_LIGHT_COUNT_STEP
#define LIDR_LIGHT_COUNT_STEP 1.0  // an 8-bit light sum (the RGBA8 G-buffer without half floats) counts in 1 / 255
#endif

void main() {
    LidrSurface s;
    if (!lidrGBufferSurface(s)) discard;
    vec4 posRadius, spot;
    vec3 lightColor;
    lidrFetchLight(uLightIndex, posRadius, lightColor, spot);
#ifdef LIDR_SHADOWS
    lightColor *= lidrShadowVisibility(s.position, posRadius, spot, lidrFetchShadowTile(uLightIndex));
#endif
    gl_FragColor = vec4(lidrShadeLight(s, posRadius, lightColor, spot), LIDR_LIGHT_COUNT_STEP);
}
