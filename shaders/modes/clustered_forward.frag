#version 120
// Clustered forward shading: the lights of this fragment's cluster (its screen tile and view-depth slice), from
// the cluster grid, with lidr's one shading function. GLSL ES 1.00-class compilers want a constant loop bound:
// LIDR_MAX_CLUSTER_LIGHTS is at least the longest cluster list of the frame (the renderer recompiles with a larger
// bound when a list outgrows it), and the loop breaks at the list's 0 terminator.
// LIDR_CLUSTER_SLICE_OUTPUT: writes the fragment's slice (red, slice / 255) instead, for the CPU checks of which
// cluster each pixel read (ClusteredRenderer::pixelSlices).
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"
#include "cluster_grid.glsl"

void main() {
    LidrSurface s = lidrSurface();
#ifdef LIDR_CLUSTER_SLICE_OUTPUT
    gl_FragColor = vec4(lidrClusterSlice(s.position) * (1.0 / 255.0), 0.0, 0.0, 1.0);
#else
    vec3 color = lidrAmbient(s) + lidrDirectionalLights(s);
    float offset = lidrClusterListOffset(s.position);
    for (int i = 0; i < LIDR_MAX_CLUSTER_LIGHTS; ++i) {
        float index = lidrClusterListEntry(offset + float(i));
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
#endif
}
