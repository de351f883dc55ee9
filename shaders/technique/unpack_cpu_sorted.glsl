// Unpack for CPU overlap sorting (lidr/technique/cpu_sorted_scheme.h). Slot g is light group g's channel share in the
// channel stream: 8-bit one channel, 16-bit two (low byte, high byte), 4-bit a nibble (even groups the low
// nibble, odd groups the high nibble of one channel). Groups are independent, so an empty slot says nothing
// about the next: there is no early out (LIDR_NULL_ENDS_LIST is not defined).
// Exact bytes come from lidrBytes(); nibbles by exact division by 16 and floor; a 16-bit index is returned as its
// bytes (low, high), exact in fp16 too (low + 256 * high would need a 17-bit significand above 2048).
//   LIDR_SLOTS, LIDR_INDEX_TARGETS, LIDR_SLOT_BITS (4, 8, 16)
#include "lidr_channel_stream.glsl"

float lidrHighNibble;  // 4-bit: the odd group's nibble of the channel taken for the even group

void lidrUnpackBegin(vec2 uv) {
    lidrStreamBegin(uv);
    lidrHighNibble = -1.0;
}

// Returns the index as its bytes (low, high).
vec2 lidrUnpackNext() {
#if LIDR_SLOT_BITS == 4
    if (lidrHighNibble > -0.5) {
        float index = lidrHighNibble;
        lidrHighNibble = -1.0;
        return vec2(index, 0.0);
    }
    float byte = lidrTakeChannel();
    lidrHighNibble = floor(byte * (1.0 / 16.0));
    return vec2(byte - lidrHighNibble * 16.0, 0.0);
#elif LIDR_SLOT_BITS == 16
    float low = lidrTakeChannel();
    float high = lidrTakeChannel();
    return vec2(low, high);  // never low + high * 256: above 2048 that does not fit an fp16 value
#else
    return vec2(lidrTakeChannel(), 0.0);
#endif
}
