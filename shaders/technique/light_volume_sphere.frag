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
//   LIDR_SPAN_SAMPLES N (MSAA, sphere-span where the context has multisample textures; GLSL 1.50): each of the N
//                   samples' shaded points (DepthSpanPass sample distances, four a texel): the light is kept
//                   where its sphere (and cone) reaches any of them (the centre's is sample 0's); with
//                   LIDR_SPHERE_RAY the ray ends at the farthest of them (the far plane where one sees none).
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
// Per side of the centre (its b: samples past it, a: before it, as fractions of the samples), the means over all
// samples of x and x^2 (rg: past, ba: before), x the sample's view distance from the centre's times
// uSpanMomentScale: each side's samples lie within Samuelson's bounds, a point where they share one surface.
uniform sampler2D uSpanSides;
uniform float uSpanSamples;
uniform float uSpanMomentScale;
uniform vec2 uSpanRounding;    // (relative, absolute) rounding of a resolved mean (DepthSpanPass::sideRounding)
uniform float uSpanSideMargin; // samples within this window depth of the centre's are on neither side

// DepthSpanPass::sideBounds: the [lowest, highest] distance from the centre of a side's k samples.
vec2 lidrSideBounds(float k, vec2 m) {
    float m1Low = max(m.x - uSpanRounding.y, 0.0) / (1.0 + uSpanRounding.x);
    float m1High = (m.x + uSpanRounding.y) / (1.0 - uSpanRounding.x);
    float m2High = (m.y + uSpanRounding.y) / (1.0 - uSpanRounding.x);
    float perSample = uSpanSamples / max(k, 1.0);
    float meanLow = m1Low * perSample;
    float spread = sqrt(max((k - 1.0) * (m2High * perSample - meanLow * meanLow), 0.0));
    return vec2(max(meanLow - spread, 0.0), m1High * perSample + spread) / uSpanMomentScale;
}
#endif

// Squared distance from the light to the closest point of the pixel's ray between distances a and b.
float lidrSegmentDistance2(vec3 ray, float toCentre, float a, float b, vec3 light) {
    vec3 d = ray * clamp(toCentre, a, b) - light;
    return dot(d, d);
}

varying vec4 vLightView;
#ifdef LIDR_SPOT_CONES
varying vec4 vConeView;  // LIDR_SPOT_CONES: a draw with spot lights (a draw of point lights alone goes without)
#endif

#ifdef LIDR_SPAN_SAMPLES
#define LIDR_SAMPLE_DISTANCE_COUNT LIDR_SPAN_SAMPLES
#include "sample_distances.glsl"  // per sample, the view distance of the point it shades (0: none), four a texel

#ifndef LIDR_SPHERE_RAY
// Whether the light reaches a surface between distances a and b on the ray (opaque lists): the segment overlaps
// the stretch of the ray inside the sphere, [enter, exit] (lidrSamplesReached), and lies in the cone, whose ramp
// must be >= 0 at one end (see the cone test in main).
bool lidrReaches(vec3 ray, float a, float b, float enter, float exit) {
    if (a > exit || b < enter) return false;
#ifdef LIDR_SPOT_CONES
    vec3 dNear = ray * a - vLightView.xyz, dFar = ray * b - vLightView.xyz;
    return dot(dNear, vConeView.xyz) + vConeView.w * length(dNear) >= 0.0 ||
           dot(dFar, vConeView.xyz) + vConeView.w * length(dFar) >= 0.0;
#else
    return true;
#endif
}
#endif

// Each sample's point (a hair wide for the rounding of its stored distance; the centre's surface is sample 0's,
// DepthSpanPass::writeCentreDepth, so the depth copy is not read): whether the light reaches one (with
// LIDR_SPHERE_RAY: meets the ray up to the farthest, or the far plane where a sample sees no surface), and the
// nearest and farthest of them. The ray runs inside the sphere between distances toCentre -/+ the half chord
// (nowhere where it passes outside): one square root a fragment, then two compares a sample instead of a
// distance to the light (the radius's hair, 1.0005, dwarfs the rounding of either).
bool lidrSamplesReached(vec3 ray, float toCentre, out float spanNear, out float spanFar) {
    float r2 = vLightView.w * uRadiusScale * vLightView.w * uRadiusScale;
    spanNear = 1e30;
    spanFar = 0.0;
    bool reached = false, empty = false;
#ifndef LIDR_SPHERE_RAY
    vec3 closest = ray * toCentre - vLightView.xyz;
    float halfChord2 = (r2 - dot(closest, closest)) / dot(ray, ray);
    float halfChord = sqrt(max(halfChord2, 0.0));
    float enter = halfChord2 >= 0.0 ? toCentre - halfChord : 1e30, exit = toCentre + halfChord;
#endif
    LidrSampleDistances distances = lidrReadSampleDistances(ivec2(gl_FragCoord.xy));
    for (int i = 0; i < LIDR_SPAN_SAMPLES; ++i) {  // a constant: the loop unrolls
        float x = lidrSampleDistance(distances, i);
        empty = empty || x <= 0.0;
        if (x <= 0.0) continue;
        float a = x * (1.0 - 1.0 / 4096.0), b = x * (1.0 + 1.0 / 4096.0);
#ifndef LIDR_SPHERE_RAY
        reached = reached || lidrReaches(ray, a, b, enter, exit);
#ifndef LIDR_SHADOWS
        if (reached) return true;  // (the shadow test needs the whole span)
#endif
#endif
        spanNear = min(spanNear, a);
        spanFar = max(spanFar, b);
    }
#ifdef LIDR_SPHERE_RAY
    if (empty) spanFar = uDepthToDistance.x / (1.0 + uDepthToDistance.y);  // the far plane
    reached = lidrSegmentDistance2(ray, toCentre, uNearPlane, spanFar, vLightView.xyz) <= r2;
#endif
    return reached;
}
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
    vec3 ray = vViewPos * (-1.0 / vViewPos.z);
    float toCentre = dot(vLightView.xyz, ray) / dot(ray, ray);
#ifdef LIDR_SPAN_SAMPLES
    float surfaceNear, surfaceFar;
    if (!lidrSamplesReached(ray, toCentre, surfaceNear, surfaceFar)) discard;
#else
    float depth = texture2D(uDepth, gl_FragCoord.xy * uInvTargetSize).r;
    float centreMargin = uDepthMargin;
#ifdef LIDR_DEPTH_SPAN
    vec2 uv = gl_FragCoord.xy * uInvTargetSize;
    vec4 span = texture2D(uDepthSpan, uv);
    vec2 excess = span.rg * uSpanBoundScale;
    bool centreSurface = depth < 1.0;
    centreMargin = max(uDepthMargin, uSpanSideMargin);
    // The sides' samples, as distances: each side one segment (a point where its samples share a surface),
    // widened a hair for the roundings of the two passes' centre distances.
    vec2 sideCount = floor(span.ba * uSpanSamples + 0.5);
    vec4 moments = texture2D(uSpanSides, uv);
    float centreDistance = centreSurface ? uDepthToDistance.x / (depth + uDepthToDistance.y) : 0.0;
    vec2 pastBounds = lidrSideBounds(sideCount.x, moments.rg), beforeBounds = lidrSideBounds(sideCount.y, moments.ba);
    float pastNear = (centreDistance + pastBounds.x) * (1.0 - 1.0 / 4096.0);
    float pastFar = (centreDistance + pastBounds.y) * (1.0 + 1.0 / 4096.0);
    float beforeNear = max(centreDistance - beforeBounds.y, 0.0) * (1.0 - 1.0 / 4096.0);
    float beforeFar = (centreDistance - beforeBounds.x) * (1.0 + 1.0 / 4096.0);
#endif
#if defined(LIDR_SPHERE_RAY)
    // The closest point to the centre on the ray between the near plane and the surface (the farthest sample's
    // with LIDR_DEPTH_SPAN; the far plane where the centre sees none).
    float surface = uDepthToDistance.x / (min(depth + centreMargin, 1.0) + uDepthToDistance.y);
#ifdef LIDR_DEPTH_SPAN
    if (centreSurface && sideCount.x > 0.5) surface = max(surface, pastFar);
#endif
    float dist2 = lidrSegmentDistance2(ray, toCentre, uNearPlane, surface, vLightView.xyz);
#else
#ifndef LIDR_DEPTH_SPAN
    if (depth >= 1.0) discard;  // background: nothing to light
#endif
    // The surface's distance is known to within the depth buffer's precision: [surfaceNear, surfaceFar] holds
    // the true surface (uDepthMargin), so the test is conservative where depth is coarse (a huge far/near
    // ratio) and marks nothing more elsewhere. The closest point to the centre on the ray where it may be:
    float surfaceNear = uDepthToDistance.x / (max(depth - centreMargin, 0.0) + uDepthToDistance.y);
    float surfaceFar = uDepthToDistance.x / (min(depth + centreMargin, 1.0) + uDepthToDistance.y);
#ifdef LIDR_DEPTH_SPAN
    // An edge pixel: the centre's surface, and each side's samples (not the air between them).
    if (!centreSurface) {
        if (sideCount.x < 0.5) discard;  // no sample shades a surface
        surfaceNear = pastNear;
        surfaceFar = pastFar;
    }
    float dist2 = lidrSegmentDistance2(ray, toCentre, surfaceNear, surfaceFar, vLightView.xyz);
    if (centreSurface && sideCount.x > 0.5)
        dist2 = min(dist2, lidrSegmentDistance2(ray, toCentre, pastNear, pastFar, vLightView.xyz));
    if (sideCount.y > 0.5)
        dist2 = min(dist2, lidrSegmentDistance2(ray, toCentre, beforeNear, beforeFar, vLightView.xyz));
    // The ends of the whole span, for the cone and shadow tests below.
    if (sideCount.x > 0.5) surfaceFar = max(surfaceFar, pastFar);
    if (sideCount.y > 0.5) surfaceNear = min(surfaceNear, beforeNear);
#else
    float dist2 = lidrSegmentDistance2(ray, toCentre, surfaceNear, surfaceFar, vLightView.xyz);
#endif
#endif
    float r = vLightView.w * uRadiusScale;
    if (dist2 > r * r) discard;
#endif
#if defined(LIDR_SPOT_CONES) && !defined(LIDR_SPHERE_RAY) && !defined(LIDR_SPAN_SAMPLES)
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
