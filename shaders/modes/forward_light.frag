#version 120
// Multi-pass forward: one light's contribution, added to the frame by the blender (ONE, ONE). The light
// comes from the shared light table by index, so every mode shades with the same light data.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"

uniform float uLightIndex;

void main() {
    LidrSurface s = lidrSurface();
    vec4 posRadius, spot;
    vec3 lightColor;
    lidrFetchLight(uLightIndex, posRadius, lightColor, spot);
#ifdef LIDR_SHADOWS
    lightColor *= lidrShadowVisibility(s.position, posRadius, spot, lidrFetchShadowTile(uLightIndex));
#endif
    gl_FragColor = vec4(lidrShadeLight(s, posRadius, lightColor, spot), 0.0);
}
