#version 150 compatibility
#extension GL_ARB_sample_shading : require
// Deferred shading's light pass under MSAA (deferred_light.frag once a sample): one light's term at the sample's
// surface from the multisampled G-buffer, added by the blender into the sample's light sum. Alpha counts the
// lighting computations, per sample.
#include "light_table.glsl"
#include "shading.glsl"
#include "shadow_lookup.glsl"
#include "g_buffer_multisample.glsl"

uniform float uLightIndex;

void main() {
    LidrSurface s;
    if (!lidrGBufferSampleSurface(s)) discard;
    vec4 posRadius, spot;
    vec3 lightColor;
    lidrFetchLight(uLightIndex, posRadius, lightColor, spot);
#ifdef LIDR_SHADOWS
    lightColor *= lidrShadowVisibility(s.position, posRadius, spot, lidrFetchShadowTile(uLightIndex));
#endif
    gl_FragColor = vec4(lidrShadeLight(s, posRadius, lightColor, spot), 1.0);
}
