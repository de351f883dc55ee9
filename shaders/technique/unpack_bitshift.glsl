// Unpack for the CONSTANT_COLOR bit-shift scheme (lidr/technique/bitshift_scheme.h). A window of LIDR_WINDOW_TARGETS
// targets holds LIDR_WINDOW_SLOTS lights; in it, channel c holds bits [c*k, c*k + k) of each index, the most
// recently drawn light's group on top. Budget 16 has two windows (ranks 0-7, then 8-15), read in turn; budget 32
// (4- and 8-bit indices) four, the third and fourth read only by a pixel whose list runs past 16.
// Bytes are rebuilt exactly by lidrBytes() (any read within +-0.45 step, fp16 and up); after that every value
// is an integer below 256, and so are the index's two bytes: the channel groups are weighted into the low byte
// (LIDR_WEIGHTS_LOWt, groups below bit 8) and the high byte (LIDR_WEIGHTS_HIGHt, groups from bit 8, weight / 256)
// separately, so every width is exact in fp16 too (an index above 2048 never exists as one fp16 value).
// No integer or bit operations: GLSL 1.20.
//   LIDR_SLOTS, LIDR_INDEX_TARGETS, LIDR_WINDOWS (1, 2 or 4), LIDR_WINDOW_TARGETS (1, 2, 4), LIDR_WINDOW_SLOTS
//   LIDR_GROUP_SCALE   2^(8-k): dividing by it takes the top k bits
//   LIDR_GROUP_VALUES  2^k: multiplying by it shifts the remaining bits up by k
//   LIDR_WEIGHTS_LOWt  weights 2^(c*k) of target t's channels c = 4t..4t+3 in a window whose group lies below
//                      bit 8, zero elsewhere; LIDR_WEIGHTS_HIGHt: 2^(c*k - 8) for groups from bit 8
#define LIDR_NULL_ENDS_LIST 1
#include "lidr_bytes.glsl"
#include "lidr_index_samplers.glsl"

vec4 lidrP0, lidrP1, lidrP2, lidrP3;  // the current window's bytes not yet unpacked, as integers
vec4 lidrQ0, lidrQ1, lidrQ2, lidrQ3;  // the second window's
float lidrLeft;                       // slots left in the current window
#if LIDR_WINDOWS > 2
vec4 lidrR0, lidrR1, lidrS0, lidrS1;  // budget 32: the third and fourth windows' (zero unless a list runs past 16)
#endif

void lidrUnpackBegin(vec2 uv) {
    lidrP1 = lidrP2 = lidrP3 = lidrQ0 = lidrQ1 = lidrQ2 = lidrQ3 = vec4(0.0);
    lidrP0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex0, uv));
#if LIDR_WINDOW_TARGETS == 1 && LIDR_WINDOWS > 1
    lidrQ0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex1, uv));
#endif
#if LIDR_WINDOW_TARGETS == 2
    lidrP1 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex1, uv));
#if LIDR_WINDOWS > 1
    lidrQ0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex2, uv));
    lidrQ1 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex3, uv));
#endif
#endif
#if LIDR_WINDOW_TARGETS == 4
    lidrP1 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex1, uv));
    lidrP2 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex2, uv));
    lidrP3 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex3, uv));
#if LIDR_WINDOWS > 1
    lidrQ0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex4, uv));
    lidrQ1 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex5, uv));
    lidrQ2 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex6, uv));
    lidrQ3 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex7, uv));
#endif
#endif
#if LIDR_WINDOWS > 2
    // Budget 32: the third and fourth windows are read only where the second is full, i.e. its oldest light's
    // group (the lowest k bits of a channel, nonzero in some channel for any index >= 1) is there: a list past 16,
    // which few pixels have. A GPU that branches skips the four fetches elsewhere; llvmpipe runs both sides of a
    // branch under a mask, so there they cost every fragment (forward pass 575 -> 630 M instructions, hall-255
    // 128x96 MSAA 4x, callgrind), the same as reading them unconditionally or inside the light loop.
    lidrR0 = lidrR1 = lidrS0 = lidrS1 = vec4(0.0);
    vec4 oldest = mod(lidrQ0, LIDR_GROUP_VALUES) + mod(lidrQ1, LIDR_GROUP_VALUES);
    if (dot(oldest, vec4(1.0)) > 0.5) {
#if LIDR_WINDOW_TARGETS == 1
        lidrR0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex2, uv));
        lidrS0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex3, uv));
#else
        lidrR0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex4, uv));
        lidrR1 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex5, uv));
        lidrS0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex6, uv));
        lidrS1 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex7, uv));
#endif
    }
#endif
    lidrLeft = LIDR_WINDOW_SLOTS;
}

// The top k bits of each channel, and the rest shifted up into their place.
vec4 lidrTakeTop(inout vec4 bytes) {
    vec4 top = floor(bytes * (1.0 / LIDR_GROUP_SCALE));
    bytes = (bytes - top * LIDR_GROUP_SCALE) * LIDR_GROUP_VALUES;
    return top;
}

// One window channel set's contribution to the index bytes (low, high).
vec2 lidrHalves(inout vec4 bytes, vec4 low, vec4 high) {
    vec4 top = lidrTakeTop(bytes);
    return vec2(dot(top, low), dot(top, high));
}

vec2 lidrUnpackNext() {
#if LIDR_WINDOWS > 1
    if (lidrLeft < 0.5) {
        lidrP0 = lidrQ0;
        lidrP1 = lidrQ1;
        lidrP2 = lidrQ2;
        lidrP3 = lidrQ3;
#if LIDR_WINDOWS > 2
        lidrQ0 = lidrR0;
        lidrQ1 = lidrR1;
        lidrR0 = lidrS0;
        lidrR1 = lidrS1;
#endif
        lidrLeft = LIDR_WINDOW_SLOTS;
    }
#endif
    lidrLeft -= 1.0;
    vec2 index = lidrHalves(lidrP0, LIDR_WEIGHTS_LOW0, LIDR_WEIGHTS_HIGH0);
#if LIDR_WINDOW_TARGETS > 1
    index += lidrHalves(lidrP1, LIDR_WEIGHTS_LOW1, LIDR_WEIGHTS_HIGH1);
#endif
#if LIDR_WINDOW_TARGETS > 2
    index += lidrHalves(lidrP2, LIDR_WEIGHTS_LOW2, LIDR_WEIGHTS_HIGH2);
    index += lidrHalves(lidrP3, LIDR_WEIGHTS_LOW3, LIDR_WEIGHTS_HIGH3);
#endif
    return index;
}
