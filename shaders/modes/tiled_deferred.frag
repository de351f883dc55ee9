#version 120
// Tiled deferred shading, full screen: the G-buffer's surface lit by the lights of its tile's list (the light grid
// tiled forward builds, tiled_grid.glsl), with the ambient, environment, emission and directional terms, through the
// output transform. LIDR_MAX_TILE_LIGHTS bounds the loop as in tiled_forward.frag.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"
#include "tiled_grid.glsl"
#include "g_buffer.glsl"

void main() {
    LidrSurface s;
    if (!lidrGBufferSurface(s)) discard;
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
    gl_FragColor = lidrOutput(color, 1.0);
}
