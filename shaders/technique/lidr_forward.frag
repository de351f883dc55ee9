#version 120
// LIDR forward pass, the built-in material: lidr's shading (shading.glsl) summed over this pixel's light
// list, then the output transform, read with the same API a user material shader has (lidr_lights.glsl; LidrOptions::materialShader).
#include "lidr_depth.glsl"
#include "shading.glsl"
#include "lidr_lights.glsl"

void main() {
    lidrWriteDepth();
    LidrSurface s = lidrSurface();
    vec3 color = lidrAmbient(s) + lidrDirectionalLights(s);
    lidrBeginLights();
    LidrLight light;
    for (int i = 0; i < LIDR_MAX_LIGHTS; ++i) {
        if (!lidrNextLight(light)) break;
#ifdef LIDR_SHADOWS
        light.color *= lidrLightShadow(light, s.position);  // as the reference shades: colour x visibility
#endif
        color += lidrShadeLight(s, vec4(light.position, light.radius), light.color, light.spot);
    }
    gl_FragColor = lidrOutput(color, uMaterialOpacity);
}
