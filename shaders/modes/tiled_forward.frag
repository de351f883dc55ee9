#version 120
// Tiled forward shading: the lights of this fragment's tile, from the light grid, with lidr's one shading
// function. GLSL ES 1.00-class compilers want a constant loop bound: LIDR_MAX_TILE_LIGHTS is at least the
// longest tile list of the frame (the renderer recompiles with a larger bound when a list outgrows it), and
// the loop breaks at the list's 0 terminator.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"
#include "tiled_grid.glsl"

#ifdef LIDR_SKIP_HIDDEN
// MSAA: llvmpipe runs the shader of a fragment whose early depth test failed at every sample (its multisample
// path does not branch on the emptied mask), and such a fragment would walk its whole tile list. A fragment behind
// the farthest depth any of the pixel's samples keeps (the pre-Z centre depth plus the span past it, as
// light_volume_sphere.frag reads them; both at the pixel centre, where this fragment's depth is) fails the depth
// test at every sample, so it skips the list. The skipped fragments write nothing: the colour is unchanged.
// Opaque fragments only (uSkipHidden 1): the spans hold, at the centre, the depth of every opaque surface that wins
// a sample, so a winner is never skipped; a transparent one (a pane standing in the floor) may win a sample while
// its centre depth lies past them.
#include "depth_pack.glsl"
uniform sampler2D uSkipCentreDepth;  // the pre-Z copy, packed (tile_depth_bounds.h)
uniform sampler2D uSkipDepthSpan;    // DepthSpanPass: r = past the centre (times the bound scale)
uniform float uSkipSpanBoundScale;
uniform vec2 uSkipInvTargetSize;
uniform float uSkipHidden;  // 1: the opaque pass; 0: transparent meshes

bool lidrHiddenAtEverySample() {
    if (uSkipHidden < 0.5) return false;
    vec2 uv = gl_FragCoord.xy * uSkipInvTargetSize;
    float centre = lidrUnpackDepthUnits(texture2D(uSkipCentreDepth, uv)) * (1.0 / kLidrDepthUnits);
    float past = texture2D(uSkipDepthSpan, uv).r * uSkipSpanBoundScale;
    float farthest = centre < 1.0 ? centre + past : min(past, 1.0);  // background centre: the span's anchor is 0
    return gl_FragCoord.z > farthest + 1.0 / 65536.0;
}
#endif

void main() {
    LidrSurface s = lidrSurface();
    vec3 color = lidrAmbient(s) + lidrDirectionalLights(s);
    float offset = lidrTileListOffset();
#ifdef LIDR_SKIP_HIDDEN
    bool hidden = lidrHiddenAtEverySample();
#else
    bool hidden = false;
#endif
    for (int i = 0; i < LIDR_MAX_TILE_LIGHTS; ++i) {
        if (hidden) break;
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
