#version 120
// Deferred shading's last pass, full screen: the light-independent terms (ambient, environment, emission: lidrAmbient)
// and the directional lights at the G-buffer's surface, plus the point and spot lights summed in the accumulation
// target, through the output transform. Pixels without a surface keep the background the pass was cleared to.
#include "shading.glsl"
#include "g_buffer.glsl"

uniform sampler2D uLightSum;

void main() {
    LidrSurface s;
    if (!lidrGBufferSurface(s)) discard;
    vec3 lights = texture2D(uLightSum, gl_FragCoord.xy * uGBufferInvSize).rgb;
    gl_FragColor = lidrOutput(lidrAmbient(s) + lidrDirectionalLights(s) + lights, 1.0);
}
