#version 150 compatibility
#extension GL_ARB_sample_shading : require
// Tiled deferred shading under MSAA (tiled_deferred.frag once a sample): the sample's surface from the multisampled
// G-buffer lit by its pixel's tile list, through the output transform, into the MSAA colour target the frame's
// resolve averages.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"
#include "tiled_grid.glsl"
#include "g_buffer_multisample.glsl"

void main() {
    LidrSurface s;
    if (!lidrGBufferSampleSurface(s)) discard;
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
