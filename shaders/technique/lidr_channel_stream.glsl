// The bytes of the index targets as one stream of channels: target 0 R, G, B, A, then target 1 R, ... .
// lidrStreamBegin(uv) reads every target (exact bytes through lidrBytes); lidrTakeChannel() returns the next
// byte. Data movement only: no arithmetic touches the bytes. LIDR_INDEX_TARGETS: 1..8.
#include "lidr_bytes.glsl"
#include "lidr_index_samplers.glsl"

vec4 lidrS0, lidrS1, lidrS2, lidrS3, lidrS4, lidrS5, lidrS6, lidrS7;  // targets not yet taken, S0 first
float lidrS0Left;                                                      // channels left in S0

void lidrStreamBegin(vec2 uv) {
    lidrS1 = lidrS2 = lidrS3 = lidrS4 = lidrS5 = lidrS6 = lidrS7 = vec4(0.0);
    lidrS0 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex0, uv));
#if LIDR_INDEX_TARGETS > 1
    lidrS1 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex1, uv));
#endif
#if LIDR_INDEX_TARGETS > 2
    lidrS2 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex2, uv));
#endif
#if LIDR_INDEX_TARGETS > 3
    lidrS3 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex3, uv));
#endif
#if LIDR_INDEX_TARGETS > 4
    lidrS4 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex4, uv));
#endif
#if LIDR_INDEX_TARGETS > 5
    lidrS5 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex5, uv));
#endif
#if LIDR_INDEX_TARGETS > 6
    lidrS6 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex6, uv));
#endif
#if LIDR_INDEX_TARGETS > 7
    lidrS7 = lidrBytes(LIDR_FETCH_INDEX(uIndexTex7, uv));
#endif
    lidrS0Left = 4.0;
}

float lidrTakeChannel() {
    if (lidrS0Left < 0.5) {
        lidrS0 = lidrS1;
        lidrS1 = lidrS2;
        lidrS2 = lidrS3;
        lidrS3 = lidrS4;
        lidrS4 = lidrS5;
        lidrS5 = lidrS6;
        lidrS6 = lidrS7;
        lidrS0Left = 4.0;
    }
    float byte = lidrS0.x;
    lidrS0 = vec4(lidrS0.yzw, 0.0);
    lidrS0Left -= 1.0;
    return byte;
}
