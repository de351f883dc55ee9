// Light table: light i's data sits in texel (i mod 256, floor(i / 256)) of 256-wide textures, looked up at
// texel centres with NEAREST filtering (never at i/256, which is a texel edge). Index 0 is the null light.
// Float path (ARB_texture_float): uLightPosRadius = (x, y, z, radius), uLightColor = (r, g, b, point light).
// Fixed path (no float textures): 16-bit fixed point in two RGBA8 textures (high and low bytes), position
// relative to the light bounds, radius relative to uLightRadiusScale; colour RGBA8 times uLightColorScale.
// Every texture has two blocks of rows (uLightTableRows is both): the light, then at v + 0.5 its spot cone,
// the vec4 lidrShadeLight takes ((0, 0, 0, 1) for a point light; lidr::spotCone): float, it is stored as it
// is in uLightPosRadius; fixed, as the axis ((d + 1) / 2) and cos(outer) in the 16-bit position textures and
// cos(inner) in the colour's red and green bytes. The colour's alpha says which: 0 a spot light, 1 a point light
// (lidr/render/light_table.cpp). A glTF light (inverse-square falloff) comes out with a negative radius, the sign
// lidrShadeLight reads: float, it is stored so; fixed, its colour's alpha byte is 1..254, code = byte - 1 holding
// a spot flag (code >= 127) and the exponent e = code mod 127 - 63 of its own colour scale 2^e (candela span many
// octaves between lights, which one shared scale would flatten into 8-bit steps of the brightest).
uniform sampler2D uLightPosRadius;
uniform sampler2D uLightColor;
uniform float uLightTableRows;
#ifdef LIDR_LIGHT_TABLE_FIXED16
uniform sampler2D uLightPosRadiusLow;
uniform vec3 uLightBoundsMin;
uniform vec3 uLightBoundsExtent;
uniform float uLightRadiusScale;
uniform float uLightColorScale;
#endif

vec2 lidrLightTexCoord(float index) {
    float row = floor(index * (1.0 / 256.0));
    float column = index - row * 256.0;
    return vec2((column + 0.5) * (1.0 / 256.0), (row + 0.5) / uLightTableRows);
}

// The same from the index's two bytes (low, high) = (column, row), never formed into one number: an index above
// 2048 does not fit one fp16 value, each byte does (LIDR's forward pass; doc/packing.md, "Precision").
vec2 lidrLightTexCoord(vec2 halves) {
    return vec2((halves.x + 0.5) * (1.0 / 256.0), (halves.y + 0.5) / uLightTableRows);
}

void lidrFetchLightAt(vec2 uv, out vec4 posRadius, out vec3 color, out vec4 spot) {
    // The colour's alpha is 0 for a spot light, 1 for a point light: a frame of point lights skips the cone fetch.
    vec4 colorTexel = texture2D(uLightColor, uv);
    spot = vec4(0.0, 0.0, 0.0, 1.0);
    vec2 coneUv = uv + vec2(0.0, 0.5);
#ifdef LIDR_LIGHT_TABLE_FIXED16
    // Bytes come back as k/255; (high * 256 + low) / 65535 rebuilds the 16-bit fraction.
    vec4 high = texture2D(uLightPosRadius, uv);
    vec4 low = texture2D(uLightPosRadiusLow, uv);
    vec4 unit = (high * (255.0 * 256.0) + low * 255.0) * (1.0 / 65535.0);
    posRadius = vec4(uLightBoundsMin + unit.xyz * uLightBoundsExtent, unit.w * uLightRadiusScale);
    color = colorTexel.rgb * uLightColorScale;
    float alphaByte = floor(colorTexel.a * 255.0 + 0.5);
    bool spotLight = alphaByte < 0.5;
    if (alphaByte > 0.5 && alphaByte < 254.5) {
        float code = alphaByte - 1.0;
        spotLight = code > 126.5;
        color = colorTexel.rgb * exp2(code - (spotLight ? 127.0 : 0.0) - 63.0);
        posRadius.w = -posRadius.w;
    }
    if (spotLight) {
        vec4 cone = (texture2D(uLightPosRadius, coneUv) * (255.0 * 256.0) +
                     texture2D(uLightPosRadiusLow, coneUv) * 255.0) * (1.0 / 65535.0);
        vec4 innerBytes = texture2D(uLightColor, coneUv);
        float cosInner = (innerBytes.r * (255.0 * 256.0) + innerBytes.g * 255.0) * (1.0 / 65535.0);
        float scale = 1.0 / max(1e-3, cosInner - cone.w);
        spot = vec4(normalize(cone.xyz * 2.0 - 1.0) * scale, -cone.w * scale);
    }
#else
    posRadius = texture2D(uLightPosRadius, uv);
    color = colorTexel.rgb;
    if (colorTexel.a < 0.5) spot = texture2D(uLightPosRadius, coneUv);
#endif
}

void lidrFetchLight(float index, out vec4 posRadius, out vec3 color, out vec4 spot) {
    lidrFetchLightAt(lidrLightTexCoord(index), posRadius, color, spot);
}

void lidrFetchLight(vec2 halves, out vec4 posRadius, out vec3 color, out vec4 spot) {
    lidrFetchLightAt(lidrLightTexCoord(halves), posRadius, color, spot);
}

#ifdef LIDR_SHADOWS
// The first shadow-atlas tile of a light's maps (shadow_lookup.glsl), -1 for a light that casts no shadow: the
// colour texture's cone block holds tile + 1 (0: none) in blue (float) or in blue and alpha as low and high
// bytes (fixed point; the red and green bytes there are a spot's cos(inner)).
float lidrFetchShadowTileAt(vec2 uv) {
    vec4 texel = texture2D(uLightColor, uv + vec2(0.0, 0.5));
#ifdef LIDR_LIGHT_TABLE_FIXED16
    return floor(texel.b * 255.0 + 0.5) + floor(texel.a * 255.0 + 0.5) * 256.0 - 1.0;
#else
    return texel.b - 1.0;
#endif
}

float lidrFetchShadowTile(float index) {
    return lidrFetchShadowTileAt(lidrLightTexCoord(index));
}

float lidrFetchShadowTile(vec2 halves) {
    return lidrFetchShadowTileAt(lidrLightTexCoord(halves));
}
#endif
