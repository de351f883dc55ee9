// Unpack for the MAX blend + stencil scheme (lidr/technique/max_stencil_scheme.h). Each stencil rank window owns two
// channels of the channel stream (target 0 RG, BA, target 1 RG, ...).
// 4/8-bit, windows of two lights: (max index, 255 - min index). An empty window reads (0, 0) and would give
// 0 and 255; a window with one light reads (a, 255 - a) and would give a twice: both are returned as the null
// light. Windows fill in rank order, so the first null ends the list.
// 16-bit, windows of one light: (low byte, high byte). Exact bytes come from lidrBytes(); the index is returned
// as those two bytes, exact in fp16 too (low + 256 * high would need a 17-bit significand above 2048).
//   LIDR_SLOTS, LIDR_INDEX_TARGETS, LIDR_WINDOW_SLOTS (1 or 2), LIDR_INDEX_HALVES (16-bit: defined)
#define LIDR_NULL_ENDS_LIST 1
#include "lidr_channel_stream.glsl"

float lidrSecond;  // the lower index of the current two-light window, returned next (0 if none)
float lidrSecondPending;

void lidrUnpackBegin(vec2 uv) {
    lidrStreamBegin(uv);
    lidrSecond = 0.0;
    lidrSecondPending = 0.0;
}

// Returns the index as its bytes (low, high).
vec2 lidrUnpackNext() {
#if LIDR_WINDOW_SLOTS == 2
    if (lidrSecondPending > 0.5) {
        lidrSecondPending = 0.0;
        return vec2(lidrSecond, 0.0);
    }
    float high = lidrTakeChannel();
    float low = 255.0 - lidrTakeChannel();
    lidrSecond = (high < 0.5 || abs(low - high) < 0.5) ? 0.0 : low;
    lidrSecondPending = 1.0;
    return vec2(high, 0.0);
#elif defined(LIDR_INDEX_HALVES)
    float low = lidrTakeChannel();
    float high = lidrTakeChannel();
    return vec2(low, high);  // never low + high * 256: above 2048 that does not fit an fp16 value
#else
    float index = lidrTakeChannel();
    lidrTakeChannel();  // 255 - index: redundant with one light per window
    return vec2(index, 0.0);
#endif
}
