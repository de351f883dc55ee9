// The light list of this pixel, for any fragment shader drawn by LIDR's forward pass (GLSL 1.20). A material
// shader (LidrOptions::materialShader, doc/embedding.md) says #include "lidr_lights.glsl" and gets:
//
//   LidrLight light;                          // position, radius, color (world space), index (1-based), spot
//   lidrBeginLights();                        // unpacks this pixel's lists (once per fragment)
//   for (int i = 0; i < LIDR_MAX_LIGHTS; ++i) {
//       if (!lidrNextLight(light)) break;     // false: no more lights on this pixel
//       ... light.position, light.radius, light.color ...
//   }
//   lidrLightShadow(light, worldPosition)   // 1 lit, 0 shadowed by the light's shadow map (1 without shadows)
//
// LIDR_MAX_LIGHTS is the budget (slots a pixel holds); the bounded loop is what GL 2.1 hardware compiles. On
// desktop GL it is a uniform int (lidr sets it): a bound the compiler cannot see keeps the loop a loop. Unrolled
// (Mesa unrolls short constant loops), a SIMD rasteriser runs every iteration under a mask however short the
// pixel's list: budget 4 cost twice budget 8 on llvmpipe (doc/benchmarks.md). GLSL ES 1.00 wants a constant.
// Attenuation is the material's business: lidr's own is clamp(1 - d^2 / r^2, 0, 1), glTF's lights (a negative
// light.radius, the range being -radius) the inverse square with KHR_lights_punctual's window (lidrShadeLight in
// shading.glsl, which also gives the surface varyings, material uniforms and the BRDF).
// lidr fills uInvViewportSize, the index textures uIndexTex0.. and the light table (light_table.glsl); the
// packing scheme's unpack file stands in for "lidr_unpack.glsl" (it defines LIDR_SLOTS, lidrUnpackBegin(uv),
// lidrUnpackNext() returning the index as (low byte, high byte), and, where the first empty slot ends the list,
// LIDR_NULL_ENDS_LIST).
// Index targets are read through LIDR_INDEX_SAMPLER / LIDR_FETCH_INDEX, so the per-sample MSAA path can swap
// in sampler2DMS and texelFetch(..., gl_SampleID) (lidr/technique/forward_pass.cpp) without touching the
// unpack files.
// LIDR_NO_LIGHTS (a frame where no light reaches a visible surface): the same API over an empty list; no index
// texture or light table is declared or read.
// LIDR_VISIBLE_SAMPLES (the opaque pass under MSAA, doc/msaa-transparency.md): lidrBeginLights() gives a fragment
// hidden at every sample an empty list; the program, a material shader's too, is then compiled as GLSL 1.50
// compatibility.
struct LidrLight {
    vec3 position;
    float radius;
    vec3 color;
    float index;       // the light's entry in the light table (its index in the frame's light list plus one, 0
                       // being the null light; with region-local indices, row * 256 + the region's index); above
                       // 2048 not exact where fragments compute in fp16
    vec2 indexBytes;   // the same as its two bytes (low, high): exact in any precision
    vec4 spot;         // the spot cone (axis x scale, offset) lidrShadeLight takes; (0, 0, 0, 1): a point light
};

void lidrNoLight(out LidrLight light) {
    light.position = vec3(0.0);
    light.radius = 0.0;
    light.color = vec3(0.0);
    light.index = 0.0;
    light.indexBytes = vec2(0.0);
    light.spot = vec4(0.0, 0.0, 0.0, 1.0);
}

#ifdef LIDR_NO_LIGHTS
#define LIDR_MAX_LIGHTS 1
void lidrBeginLights() {}
bool lidrNextLight(out LidrLight light) {
    lidrNoLight(light);
    return false;
}
#else
#ifndef LIDR_INDEX_SAMPLER
#define LIDR_INDEX_SAMPLER sampler2D
#define LIDR_FETCH_INDEX(s, uv) texture2D(s, uv)
#endif
#include "light_table.glsl"
#include "lidr_unpack.glsl"

#ifdef GL_ES
#define LIDR_MAX_LIGHTS LIDR_SLOTS
#else
uniform int uLidrMaxLights;  // LIDR_SLOTS
#define LIDR_MAX_LIGHTS uLidrMaxLights
#endif

uniform vec2 uInvViewportSize;
#ifndef GL_ES
// Region-local indices (lidr/technique/volume_tiles.h, IndexRegions; desktop GL with the float light table):
// (1 / tile size, tiles per row, first map row, 1 when on). The pixel's tile's entry in the map, kept in the
// light table's position texture from the first map row on, is the pixel's region: its row of the table, added
// to the index's high byte. Off: row 0 (global numbering). Pixel centres lie half a pixel inside a tile, so the
// floors are exact; tile numbers and rows are small integers, exact in fp32.
uniform vec4 uLidrRegionMap;
#endif

float lidrSlotsLeft;
float lidrRegionRow;

#ifndef GL_ES
float lidrRegionRowOfPixel() {
    float tile = floor(gl_FragCoord.x * uLidrRegionMap.x) + uLidrRegionMap.y * floor(gl_FragCoord.y * uLidrRegionMap.x);
    float row = floor(tile * (1.0 / 256.0));
    vec2 uv = vec2((tile - row * 256.0 + 0.5) * (1.0 / 256.0), (uLidrRegionMap.z + row + 0.5) / uLightTableRows);
    return texture2D(uLightPosRadius, uv).x;
}
#endif

#ifdef LIDR_VISIBLE_SAMPLES
// LIDR_VISIBLE_SAMPLES n (the opaque pass under MSAA with the samples' distances, GLSL 1.50 compatibility;
// ForwardPass::run): the MSAA pre-pass (depth LEQUAL, so at a depth tie the last fragment drawn writes, as the
// EQUAL test here keeps the last one) left in every sample the view distance, at the pixel centre, of the fragment
// whose colour that sample keeps. A fragment whose own distance matches none of them keeps no sample: its colour
// is rejected by the depth test or overwritten, so its list is empty. A SIMD rasteriser that runs the shader of
// fragments its early depth test rejected (llvmpipe under MSAA) then pays no lights for hidden surfaces. The match
// allows 2^-12 of the distance (the pre-pass took it from vWorldPos, this from gl_FragCoord.w: the same number but
// for rounding, far below that): a hidden fragment that close is shaded for nothing; a visible one is not skipped.
#define LIDR_SAMPLE_DISTANCE_COUNT LIDR_VISIBLE_SAMPLES
#include "sample_distances.glsl"
bool lidrKeepsASample() {
    float distance = 1.0 / gl_FragCoord.w;
    LidrSampleDistances samples = lidrReadSampleDistances(ivec2(gl_FragCoord.xy));
    bool keeps = false;
    for (int i = 0; i < LIDR_VISIBLE_SAMPLES; ++i)  // unrolled: cheaper on llvmpipe than a loop that ends early
        keeps = keeps || abs(lidrSampleDistance(samples, i) - distance) <= distance * (1.0 / 4096.0);
    return keeps;
}
#endif

void lidrBeginLights() {
    lidrUnpackBegin(gl_FragCoord.xy * uInvViewportSize);  // pixel centre -> index texel centre
    lidrSlotsLeft = float(LIDR_SLOTS);
#ifdef LIDR_VISIBLE_SAMPLES
    if (!lidrKeepsASample()) lidrSlotsLeft = 0.0;
#endif
    lidrRegionRow = 0.0;
#ifndef GL_ES
#ifdef LIDR_REGION_MAP  // the frame's shading variant (lidr/render/shading_variants.h): regions compiled in or out
#if LIDR_REGION_MAP
    lidrRegionRow = lidrRegionRowOfPixel();
#endif
#else  // a uniform branch: a SIMD rasteriser runs the lookup under a mask even where regions are off
    if (uLidrRegionMap.w > 0.5) lidrRegionRow = lidrRegionRowOfPixel();
#endif
#endif
}

void lidrSetLight(out LidrLight light, vec2 index) {
    index.y += lidrRegionRow;
    vec4 posRadius;
    vec3 color;
    lidrFetchLight(index, posRadius, color, light.spot);
    light.position = posRadius.xyz;
    light.radius = posRadius.w;
    light.color = color;
    light.index = index.x + 256.0 * index.y;
    light.indexBytes = index;
}

bool lidrNextLight(out LidrLight light) {
    lidrNoLight(light);
#ifdef LIDR_NULL_ENDS_LIST
    // One slot per call, no inner loop (unrolled inside the caller's loop it would run LIDR_SLOTS times).
    if (lidrSlotsLeft < 0.5) return false;
    lidrSlotsLeft -= 1.0;
    vec2 next = lidrUnpackNext();
    if (next.x + next.y < 0.5) {
        lidrSlotsLeft = 0.0;  // the first empty slot ends the list
        return false;
    }
    lidrSetLight(light, next);
    return true;
#else
    for (int slot = 0; slot < LIDR_SLOTS; ++slot) {
        if (lidrSlotsLeft < 0.5) return false;
        lidrSlotsLeft -= 1.0;
        // The index as its two bytes (low, high), (0, 0) for an empty slot: never one float, which fp16
        // fragments cannot hold above 2048; the light table is read at texel (low, high).
        vec2 index = lidrUnpackNext();
        if (index.x + index.y >= 0.5) {  // an empty slot is skipped: a later one may hold a light
            lidrSetLight(light, index);
            return true;
        }
    }
    return false;
#endif
}
#endif  // LIDR_NO_LIGHTS

#if defined(LIDR_SHADOWS) && !defined(LIDR_NO_LIGHTS)
// LIDR_SHADOWS (a frame with shadow-casting lights, issue 30): 1.0 where the light's shadow map leaves world point
// p lit, 0.0 where it shadows it (between them at filtered edges): the map looked up by the light's index (the
// paper's second way), its first atlas tile read from the light table. A material shader multiplies its light's
// colour by it; without LIDR_SHADOWS it is 1.0.
#include "shadow_lookup.glsl"
float lidrLightShadow(LidrLight light, vec3 p) {
    return lidrShadowVisibility(p, vec4(light.position, light.radius), light.spot, lidrFetchShadowTile(light.indexBytes));
}
#else
float lidrLightShadow(LidrLight light, vec3 p) {
    return 1.0;
}
#endif
