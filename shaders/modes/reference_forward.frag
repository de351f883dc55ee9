#version 120
// Brute-force reference: every light at every pixel, with the same shading function as every other mode.
// GLSL 1.20-class compilers want a constant loop bound, so the loop runs to LIDR_MAX_LIGHTS and breaks.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"

uniform float uLightCount;

void main() {
    LidrSurface s = lidrSurface();
    vec3 color = lidrAmbient(s) + lidrDirectionalLights(s);
    for (int i = 1; i <= LIDR_MAX_LIGHTS; ++i) {
        float index = float(i);
        if (index > uLightCount) break;
        vec4 posRadius, spot;
        vec3 lightColor;
        lidrFetchLight(index, posRadius, lightColor, spot);
#ifdef LIDR_SHADOWS
        lightColor *= lidrShadowVisibility(s.position, posRadius, spot, lidrFetchShadowTile(index));
#endif
        color += lidrShadeLight(s, posRadius, lightColor, spot);
    }
    gl_FragColor = lidrOutput(color, uMaterialOpacity);
}
