#version 120
// The exact volume test in the fragment shader: the pixel's surface point, rebuilt from a copy of the
// pre-pass depth, is tested against the light's true sphere, and every other fragment of the (coarser,
// enclosing) volume mesh is discarded before it reaches the stencil. So only lights that really reach the
// pixel are counted and written, in one draw, whatever the rank window. A spot light's fragment must also lie
// inside its cone, where the shading's cone term is above 0 (opaque lists; the front-face lists keep the sphere).
//   LIDR_SPHERE_RAY undefined: the surface point lies inside the sphere (opaque lists).
//   LIDR_SPHERE_RAY defined:   the eye ray between the near plane and the surface meets the sphere (front-face
//                              lists for transparent layers).
//   LIDR_DEPTH_SPAN (MSAA, sphere-span): the pixel's samples shade surfaces between two depths (DepthSpanPass,
//                   uDepthSpan); without LIDR_SPHERE_RAY the ray between them must meet the sphere (interior
//                   pixels: one depth, the sphere test), with it the ray ends at the farther one.
// Everything is in view space along the pixel's ray, scaled so that its z is -1: a point at distance z in
// front of the eye is ray * z. A few operations a fragment, because on a CPU rasteriser this shader runs for
// every fragment of every volume (discard and stencil writes force the late depth test there).
//   LIDR_SHADOWS (opaque lists, a draw with shadow-casting lights; the paper's first way to shadow): a fragment
//                whose surface span the light's shadow map shadows at both ends is discarded too, so the light
//                takes no slot there (the forward pass looks the lights that are left up at the point it shades).
#include "lidr_depth.glsl"
#if defined(LIDR_SHADOWS) && !defined(LIDR_SPHERE_RAY)
#include "shadow_lookup.glsl"
uniform mat4 uInvView;  // view -> world: the lookup works in world space, as every mode's shading does
varying float vShadowTile;
#endif
uniform sampler2D uDepth;      // the pre-pass depth, not attached to the framebuffer drawn into
uniform vec2 uInvTargetSize;
uniform vec2 uDepthToDistance; // window depth d -> distance in front of the eye: x / (d + y) (perspective)
uniform float uNearPlane;
uniform float uRadiusScale;    // a hair over 1: lights are kept up to here (the CPU truth's band lies inside)
uniform float uDepthMargin;    // the surface lies within this much window depth of the stored depth (a few steps)
#ifdef LIDR_DEPTH_SPAN
// Per pixel, what the samples' shaded depths lie above (r) and below (g) an anchor: the centre's depth, or 0 and
// 1 where the centre sees no surface; resolved (averaged), so times uSpanBoundScale (the sample count, with a
// rounding margin) each bounds every sample's.
uniform sampler2D uDepthSpan;
uniform float uSpanBoundScale;
#endif

varying vec4 vLightView;
#ifdef LIDR_SPOT_CONES
varying vec4 vConeView;  // LIDR_SPOT_CONES: a draw with spot lights (a draw of point lights alone goes without)
#endif
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
    lidrWriteDepth();
    float depth = texture2D(uDepth, gl_FragCoord.xy * uInvTargetSize).r;
    vec3 ray = vViewPos * (-1.0 / vViewPos.z);
    float toCentre = dot(vLightView.xyz, ray) / dot(ray, ray);
#ifdef LIDR_DEPTH_SPAN
    vec2 excess = texture2D(uDepthSpan, gl_FragCoord.xy * uInvTargetSize).rg * uSpanBoundScale;
    bool centreSurface = depth < 1.0;
    float spanNear = centreSurface ? depth - excess.g : 1.0 - excess.g;
    float spanFar = centreSurface ? depth + excess.r : min(excess.r, 1.0);
#endif
#if defined(LIDR_SPHERE_RAY)
    // The closest point to the centre on the ray between the near plane and the surface (the farthest sample's
    // with LIDR_DEPTH_SPAN; the far plane where the centre sees none).
#ifdef LIDR_DEPTH_SPAN
    if (centreSurface) depth = min(spanFar + uDepthMargin, 1.0);
#endif
    float surface = uDepthToDistance.x / (depth + uDepthToDistance.y);
    float t = clamp(toCentre, uNearPlane, surface);
#elif defined(LIDR_DEPTH_SPAN)
    if (spanNear > spanFar) discard;  // no sample shades a surface
    float surfaceNear = uDepthToDistance.x / (max(spanNear - uDepthMargin, 0.0) + uDepthToDistance.y);
    float surfaceFar = uDepthToDistance.x / (min(spanFar + uDepthMargin, 1.0) + uDepthToDistance.y);
    float t = clamp(toCentre, surfaceNear, surfaceFar);
#else
    if (depth >= 1.0) discard;  // background: nothing to light
    // The surface's distance is known to within the depth buffer's precision: [surfaceNear, surfaceFar] holds
    // the true surface (uDepthMargin), so the test is conservative where depth is coarse (a huge far/near
    // ratio) and marks nothing more elsewhere. The closest point to the centre on the ray where it may be:
    float surfaceNear = uDepthToDistance.x / (max(depth - uDepthMargin, 0.0) + uDepthToDistance.y);
    float surfaceFar = uDepthToDistance.x / (min(depth + uDepthMargin, 1.0) + uDepthToDistance.y);
    float t = clamp(toCentre, surfaceNear, surfaceFar);
#endif
    vec3 d = ray * t - vLightView.xyz;
    float r = vLightView.w * uRadiusScale;
    if (dot(d, d) > r * r) discard;
#if defined(LIDR_SPOT_CONES) && !defined(LIDR_SPHERE_RAY)
    // The cone: the shading's ramp dot(unit d, axis) x scale + offset is >= 0 at one end of the surface's span
    // (multiplied by |d|: no division, and the apex, |d| = 0, is kept). A point light's (0, 0, 0, 1) always passes.
    vec3 dNear = ray * surfaceNear - vLightView.xyz, dFar = ray * surfaceFar - vLightView.xyz;
#ifdef LIDR_DEPTH_SPAN
    // An edge pixel's span is long: a segment may cross the cone with both ends outside it, so the cone is
    // tested on interior pixels only (there the span is the surface's, as in the sphere test).
    if (excess.r + excess.g <= uDepthMargin &&
#else
    if (
#endif
        dot(dNear, vConeView.xyz) + vConeView.w * length(dNear) < 0.0 &&
        dot(dFar, vConeView.xyz) + vConeView.w * length(dFar) < 0.0)
        discard;
#endif
#if defined(LIDR_SHADOWS) && !defined(LIDR_SPHERE_RAY)
    // Both ends of the span: where the map's verdict changes inside it, the light stays and the forward pass
    // decides at its own point (so the image is the reference's, which looks up there).
    float shadowTile = floor(vShadowTile + 0.5);
    if (shadowTile >= 0.0) {
        vec4 posRadius = vec4((uInvView * vec4(vLightView.xyz, 1.0)).xyz, vLightView.w);
#ifdef LIDR_SPOT_CONES
        vec4 spot = vec4((uInvView * vec4(vConeView.xyz, 0.0)).xyz, vConeView.w);
#else
        vec4 spot = vec4(0.0, 0.0, 0.0, 1.0);
#endif
        // The far end only where the near one is shadowed: most fragments of a casting light are lit. Only where
        // the texels are settled: the forward pass's own point (interpolated, not rebuilt from depth) may lie a
        // rounding away, across a texel's edge (seen on WebGL's SwiftShader: whole lights missing at shadow edges).
        bool settled;
        if (lidrShadowVisibilitySettled((uInvView * vec4(ray * surfaceNear, 1.0)).xyz, posRadius, spot, shadowTile, settled) <= 0.0 && settled) {
            if (lidrShadowVisibilitySettled((uInvView * vec4(ray * surfaceFar, 1.0)).xyz, posRadius, spot, shadowTile, settled) <= 0.0 && settled)
                discard;
        }
    }
#endif
    gl_FragData[0] = lidrExactBytes(vColor0);
#if LIDR_DRAW_TARGETS > 1
    gl_FragData[1] = lidrExactBytes(vColor1);
#endif
#if LIDR_DRAW_TARGETS > 2
    gl_FragData[2] = lidrExactBytes(vColor2);
    gl_FragData[3] = lidrExactBytes(vColor3);
#endif
}
