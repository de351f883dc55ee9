// Shadow maps looked up by light (issue 30; lidr/render/shadow_atlas.h): where a world point falls in a light's
// map of the shadow atlas and whether the light reaches it. Every mode's shading and LIDR's volume test call
// lidrShadowVisibility, so they agree; the CPU twin is lidr/render/shadow_lookup.h.
//
// The map's camera is not stored: it follows from the light itself (position, range, spot axis and outer cone,
// as the light table holds them) and the first atlas tile the light's maps take (ShadowAtlas: tile t lies at
// column t mod uShadowAtlasLayout.x, row floor(t / uShadowAtlasLayout.x), each uShadowAtlasLayout.y of the
// atlas wide). A spot light's map looks down the axis with a field of view of twice the outer cone, its up
// vector world +y (world +x where the axis is within 0.9 of +-y); a point light's six maps are the faces of a
// cube, numbered and oriented as OpenGL's cube maps (+x, -x, +y, -y, +z, -z; spotShadowCamera and
// pointShadowCamera draw them so). Near plane at a hundredth of the range, far plane at the range.
//
// A point is shadowed when the map holds something nearer to the light than the point by more than the bias:
// uShadowBias.x texels' footprints at the point's distance plus uShadowBias.y x the range (what the 24-bit depth
// and the rasteriser's rounding need); a surface slanted towards its light is kept from shadowing itself by the
// maps' own slope-scaled offset (ShadowAtlasOptions::slopeBias, glPolygonOffset). Points outside the map's view (behind
// the near plane, outside a spot's cone) are lit: the light's own range and cone terms decide there.
// LIDR_SHADOW_PCF: the four nearest texels compared and weighted bilinearly (filtered edges); without it the
// nearest texel decides (0 or 1). LIDR_SHADOW_PACKED: the atlas is RGBA8 holding the depth in 24 bits (ES 2.0
// without OES_depth_texture), unpacked here.
#ifdef LIDR_SHADOWS
uniform sampler2D uShadowAtlas;
uniform vec4 uShadowAtlasLayout;  // tiles per row, tile width in atlas uv, texels per tile, 1 / atlas texels
uniform vec2 uShadowBias;         // texels, fraction of the range

float lidrShadowMapDepth(vec2 uv) {
#ifdef LIDR_SHADOW_PACKED
    vec3 bytes = floor(texture2D(uShadowAtlas, uv).rgb * 255.0 + 0.5);
    return dot(bytes, vec3(1.0 / 256.0, 1.0 / 65536.0, 1.0 / 16777216.0)) * (16777216.0 / 16777215.0);
#else
    return texture2D(uShadowAtlas, uv).r;
#endif
}

// The tile (first tile + cube face) and the map coordinates in [-1, 1] of world point p, with its depth along
// the map's axis. Returns false where the map does not see p.
bool lidrShadowMapCoord(vec3 p, vec4 posRadius, vec4 spot, float firstTile,
                        out float tile, out vec2 ndc, out float viewDepth, out float tanHalfFov) {
    vec3 w = p - posRadius.xyz;
    tile = firstTile;
    float spotScale = dot(spot.xyz, spot.xyz);
    if (spotScale > 0.0) {
        vec3 forward = spot.xyz * inversesqrt(spotScale);
        float cosOuter = clamp(-spot.w * inversesqrt(spotScale), 1e-4, 1.0);
        tanHalfFov = sqrt(max(1.0 - cosOuter * cosOuter, 0.0)) / cosOuter;
        vec3 up = abs(forward.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 right = normalize(cross(forward, up));
        up = cross(right, forward);
        viewDepth = dot(w, forward);
        if (viewDepth <= 0.0) return false;
        ndc = vec2(dot(w, right), dot(w, up)) / (viewDepth * tanHalfFov);
        if (abs(ndc.x) > 1.0 || abs(ndc.y) > 1.0) return false;
    } else {
        tanHalfFov = 1.0;
        vec3 a = abs(w);
        vec2 st;
        if (a.x >= a.y && a.x >= a.z) {
            viewDepth = a.x;
            tile += w.x > 0.0 ? 0.0 : 1.0;
            st = vec2(w.x > 0.0 ? -w.z : w.z, -w.y);
        } else if (a.y >= a.z) {
            viewDepth = a.y;
            tile += w.y > 0.0 ? 2.0 : 3.0;
            st = vec2(w.x, w.y > 0.0 ? w.z : -w.z);
        } else {
            viewDepth = a.z;
            tile += w.z > 0.0 ? 4.0 : 5.0;
            st = vec2(w.z > 0.0 ? w.x : -w.x, -w.y);
        }
        if (viewDepth <= 0.0) return false;
        ndc = st / viewDepth;
    }
    return true;
}

// lidrShadowVisibility (below), and whether a lookup at a point within rounding of p (the same surface point
// derived another way: LIDR's volume test rebuilds it from depth, the forward pass interpolates it) could read
// other texels: `settled` is false where p lies within 1/64 texel of where the texels it reads change (a texel's
// edge; filtered, a texel centre), or within 1/64 texel of a map's border (a cube face's edge).
float lidrShadowVisibilitySettled(vec3 p, vec4 posRadius, vec4 spot, float firstTile, out bool settled) {
    settled = true;
    if (firstTile < 0.0) return 1.0;
    float tile, viewDepth, tanHalfFov;
    vec2 ndc;
    settled = false;
    if (!lidrShadowMapCoord(p, posRadius, spot, firstTile, tile, ndc, viewDepth, tanHalfFov)) return 1.0;
    float range = abs(posRadius.w);
    float nearPlane = range * 0.01;
    if (viewDepth <= nearPlane) return 1.0;
    float texels = uShadowAtlasLayout.z;
    // The point's texel position in its tile, kept half a texel inside so no sample reads the next tile.
    vec2 unclamped = (ndc * 0.5 + 0.5) * texels;
    vec2 texel = clamp(unclamped, vec2(0.5), vec2(texels - 0.5));
    vec2 inside = min(unclamped, texels - unclamped);  // texels from the map's border
    settled = min(inside.x, inside.y) > 0.015625;
    float row = floor(tile / uShadowAtlasLayout.x + 1e-3);
    vec2 tileOrigin = vec2(tile - row * uShadowAtlasLayout.x, row) * texels;
    // Linear depth along the map's axis: window depth z = (d - n) f / ((f - n) d)  <=>  d = n f / (f - z (f - n)).
    float bias = uShadowBias.x * (2.0 * viewDepth * tanHalfFov / texels) + uShadowBias.y * range;
    float limit = viewDepth - bias;  // an occluder nearer than this shadows the point
    float farMinusNear = range - nearPlane;
#ifdef LIDR_SHADOW_PCF
    vec2 base = floor(texel - 0.5);
    vec2 f = texel - 0.5 - base;
    settled = settled && min(f.x, f.y) > 0.015625 && max(f.x, f.y) < 0.984375;
    vec4 lit;
    for (int i = 0; i < 4; ++i) {
        vec2 offset = vec2(float(i - (i / 2) * 2), float(i / 2));
        vec2 at = clamp(base + offset, vec2(0.0), vec2(texels - 1.0)) + 0.5;
        float z = lidrShadowMapDepth((tileOrigin + at) * uShadowAtlasLayout.w);
        float occluder = nearPlane * range / max(range - z * farMinusNear, 1e-30);
        lit[i] = occluder < limit ? 0.0 : 1.0;
    }
    return mix(mix(lit.x, lit.y, f.x), mix(lit.z, lit.w, f.x), f.y);
#else
    vec2 f = fract(texel);
    settled = settled && min(f.x, f.y) > 0.015625 && max(f.x, f.y) < 0.984375;
    float z = lidrShadowMapDepth((tileOrigin + floor(texel) + 0.5) * uShadowAtlasLayout.w);
    float occluder = nearPlane * range / max(range - z * farMinusNear, 1e-30);
    return occluder < limit ? 0.0 : 1.0;
#endif
}
// 1.0 where light (posRadius, spot: as the light table gives them) with its maps from atlas tile firstTile
// reaches world point p, 0.0 where the map holds an occluder; between them at filtered edges (LIDR_SHADOW_PCF).
// firstTile < 0: the light casts no shadow (1.0).
float lidrShadowVisibility(vec3 p, vec4 posRadius, vec4 spot, float firstTile) {
    bool settled;
    return lidrShadowVisibilitySettled(p, posRadius, spot, firstTile, settled);
}
#endif
