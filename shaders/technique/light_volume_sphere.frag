#version 120
// The exact volume test in the fragment shader: the pixel's surface point, rebuilt from a copy of the
// pre-pass depth, is tested against the light's true sphere, and every other fragment of the (coarser,
// enclosing) volume mesh is discarded before it reaches the stencil. So only lights that really reach the
// pixel are counted and written, in one draw, whatever the rank window.
//   LIDR_SPHERE_RAY undefined: the surface point lies inside the sphere (opaque lists).
//   LIDR_SPHERE_RAY defined:   the eye ray between the near plane and the surface meets the sphere (front-face
//                              lists for transparent layers and MSAA edge samples).
// Everything is in view space along the pixel's ray, scaled so that its z is -1: a point at distance z in
// front of the eye is ray * z. A few operations a fragment, because on a CPU rasteriser this shader runs for
// every fragment of every volume (discard and stencil writes force the late depth test there).
uniform sampler2D uDepth;      // the pre-pass depth, not attached to the framebuffer drawn into
uniform vec2 uInvTargetSize;
uniform vec2 uDepthToDistance; // window depth d -> distance in front of the eye: x / (d + y) (perspective)
uniform float uNearPlane;
uniform float uRadiusScale;    // a hair over 1: lights are kept up to here (the CPU truth's band lies inside)

varying vec4 vLightView;
varying vec3 vViewPos;
varying vec4 vColor0;
#if LIDR_DRAW_TARGETS > 1
varying vec4 vColor1;
#endif
#if LIDR_DRAW_TARGETS > 2
varying vec4 vColor2;
varying vec4 vColor3;
#endif

// Interpolation may move a constant varying by an ulp; the index value must be an exact byte.
vec4 lidrExactBytes(vec4 c) {
    return floor(c * 255.0 + 0.5) * (1.0 / 255.0);
}

void main() {
    float depth = texture2D(uDepth, gl_FragCoord.xy * uInvTargetSize).r;
    vec3 ray = vViewPos * (-1.0 / vViewPos.z);
    float surface = uDepthToDistance.x / (depth + uDepthToDistance.y);
#ifdef LIDR_SPHERE_RAY
    // The closest point to the centre on the ray between the near plane and the surface.
    float t = clamp(dot(vLightView.xyz, ray) / dot(ray, ray), uNearPlane, surface);
    vec3 d = ray * t - vLightView.xyz;
#else
    if (depth >= 1.0) discard;  // background: nothing to light
    vec3 d = ray * surface - vLightView.xyz;
#endif
    float r = vLightView.w * uRadiusScale;
    if (dot(d, d) > r * r) discard;
    gl_FragData[0] = lidrExactBytes(vColor0);
#if LIDR_DRAW_TARGETS > 1
    gl_FragData[1] = lidrExactBytes(vColor1);
#endif
#if LIDR_DRAW_TARGETS > 2
    gl_FragData[2] = lidrExactBytes(vColor2);
    gl_FragData[3] = lidrExactBytes(vColor3);
#endif
}
