// Reads the clustered-forward light grid (lidr/modes/cluster_grid.h, doc/clustered.md). GLSL 1.20 and GLSL ES
// 1.00, no integers or bit operations: bytes are rebuilt with floor(x * 255 + 0.5), exact for every 8-bit value,
// and every number stays an integer below 2^24, exact in fp32. The grid's sizes are compile-time constants:
//   LIDR_CLUSTER_TILE_SIZE       tile edge in pixels
//   LIDR_CLUSTER_TILES_X/_Y      tiles across and up
//   LIDR_CLUSTER_SLICES          depth slices (1: no depth lookup at all, the 2D tile lists)
//   LIDR_CLUSTER_SLICES_PER_ROW  slices side by side in the grid texture (the rest in rows above)
//   LIDR_CLUSTER_GRID_SIZE       the grid texture's size in texels, vec2(w, h)
//   LIDR_CLUSTER_INDEX_BITS      8: LUMINANCE8 list texels, 16: LUMINANCE8_ALPHA8 (L high)
//   LIDR_LIGHT_LIST_WIDTH        entries per row of the list texture (a power of two)
uniform sampler2D uClusterGrid;    // RGBA8 per cluster: its list's offset, 24 bits, R high
uniform sampler2D uClusterLights;  // the lists: light indices, 0 ends a list
uniform float uClusterListRows;
#if LIDR_CLUSTER_SLICES > 1
uniform vec4 uClusterDepthAxis;    // xyz: the view direction (unit, world space), w: -dot(xyz, eye)
uniform vec2 uClusterSlicing;      // slice = floor(log2(view depth) * x + y), clamped to the slices
#endif

// The depth slice of a surface point (world space). Its view depth comes from the interpolated world position in
// full precision (gl_FragCoord is mediump in GLSL ES 1.00; contexts without highp fragments get one slice); the CPU
// widens every cell so that a point next to a slice boundary is in the cell of whichever slice this rounds to.
float lidrClusterSlice(vec3 worldPos) {
#if LIDR_CLUSTER_SLICES > 1
    float depth = max(dot(uClusterDepthAxis.xyz, worldPos) + uClusterDepthAxis.w, 1e-20);
    return clamp(floor(log2(depth) * uClusterSlicing.x + uClusterSlicing.y), 0.0, float(LIDR_CLUSTER_SLICES - 1));
#else
    return 0.0;
#endif
}

// Offset of the list of this fragment's cluster: its tile from gl_FragCoord (at pixel or sample centres, x + 0.5,
// never on a tile edge), its slice from the surface point.
float lidrClusterListOffset(vec3 worldPos) {
    vec2 texel = floor(gl_FragCoord.xy * (1.0 / float(LIDR_CLUSTER_TILE_SIZE)));
#if LIDR_CLUSTER_SLICES > 1
    float slice = lidrClusterSlice(worldPos);
    float sliceRow = floor((slice + 0.5) * (1.0 / float(LIDR_CLUSTER_SLICES_PER_ROW)));
    texel += vec2((slice - sliceRow * float(LIDR_CLUSTER_SLICES_PER_ROW)) * float(LIDR_CLUSTER_TILES_X),
                  sliceRow * float(LIDR_CLUSTER_TILES_Y));
#endif
    vec3 bytes = floor(texture2D(uClusterGrid, (texel + 0.5) / LIDR_CLUSTER_GRID_SIZE).rgb * 255.0 + 0.5);
    return dot(bytes, vec3(65536.0, 256.0, 1.0));
}

float lidrClusterListEntry(float k) {
    float row = floor(k * (1.0 / float(LIDR_LIGHT_LIST_WIDTH)));
    float column = k - row * float(LIDR_LIGHT_LIST_WIDTH);
    vec2 uv = vec2((column + 0.5) * (1.0 / float(LIDR_LIGHT_LIST_WIDTH)), (row + 0.5) / uClusterListRows);
    vec4 texel = texture2D(uClusterLights, uv);
#if LIDR_CLUSTER_INDEX_BITS == 8
    return floor(texel.r * 255.0 + 0.5);
#else
    return floor(texel.r * 255.0 + 0.5) * 256.0 + floor(texel.a * 255.0 + 0.5);
#endif
}
