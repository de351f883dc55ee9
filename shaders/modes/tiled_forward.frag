#version 120
// Tiled forward shading: the lights of this fragment's tile, from the light grid, with lidr's one shading
// function. GLSL ES 1.00-class compilers want a constant loop bound: LIDR_MAX_TILE_LIGHTS is at least the
// longest tile list of the frame (the renderer recompiles with a larger bound when a list outgrows it), and
// the loop breaks at the list's 0 terminator.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"
#include "tiled_grid.glsl"

void main() {
    LidrSurface s = lidrSurface();
    vec3 color = lidrAmbient(s) + lidrDirectionalLights(s);
    float offset = lidrTileListOffset();
    for (int i = 0; i < LIDR_MAX_TILE_LIGHTS; ++i) {
        float index = lidrTileListEntry(offset + float(i));
        if (index < 0.5) break;
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
