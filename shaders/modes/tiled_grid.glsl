// Reads the tiled-forward light grid (lidr/modes/light_grid.h, doc/tiled.md). GLSL 1.20, no integers or bit ops:
// bytes are rebuilt with floor(x * 255 + 0.5), exact for every 8-bit value, and every number stays an
// integer below 2^24, exact in fp32.
//   LIDR_TILE_SIZE        tile edge in pixels
//   LIDR_LIGHT_LIST_WIDTH entries per row of the list texture (a power of two)
uniform sampler2D uTileGrid;    // RGBA8 per tile: the tile list's offset, 24 bits, R high
uniform sampler2D uLightList;   // LUMINANCE8_ALPHA8 per entry: light index, 16 bits, L high; 0 ends a list
uniform vec2 uTileGridSize;     // tiles in x and y
uniform float uLightListRows;

// Offset of this fragment's tile list. gl_FragCoord is at pixel (or sample) centres, x + 0.5, so the
// division never lands on a tile edge.
float lidrTileListOffset() {
    vec2 tile = floor(gl_FragCoord.xy * (1.0 / float(LIDR_TILE_SIZE)));
    vec3 bytes = floor(texture2D(uTileGrid, (tile + 0.5) / uTileGridSize).rgb * 255.0 + 0.5);
    return dot(bytes, vec3(65536.0, 256.0, 1.0));
}

float lidrTileListEntry(float k) {
    float row = floor(k * (1.0 / float(LIDR_LIGHT_LIST_WIDTH)));
    float column = k - row * float(LIDR_LIGHT_LIST_WIDTH);
    vec2 uv = vec2((column + 0.5) * (1.0 / float(LIDR_LIGHT_LIST_WIDTH)), (row + 0.5) / uLightListRows);
    vec4 texel = texture2D(uLightList, uv);
    return floor(texel.r * 255.0 + 0.5) * 256.0 + floor(texel.a * 255.0 + 0.5);
}
