// The index targets an unpack shader reads: uIndexTex0 .. uIndexTex(LIDR_INDEX_TARGETS - 1), 1..8 of them.
uniform LIDR_INDEX_SAMPLER uIndexTex0;
#if LIDR_INDEX_TARGETS > 1
uniform LIDR_INDEX_SAMPLER uIndexTex1;
#endif
#if LIDR_INDEX_TARGETS > 2
uniform LIDR_INDEX_SAMPLER uIndexTex2;
#endif
#if LIDR_INDEX_TARGETS > 3
uniform LIDR_INDEX_SAMPLER uIndexTex3;
#endif
#if LIDR_INDEX_TARGETS > 4
uniform LIDR_INDEX_SAMPLER uIndexTex4;
#endif
#if LIDR_INDEX_TARGETS > 5
uniform LIDR_INDEX_SAMPLER uIndexTex5;
#endif
#if LIDR_INDEX_TARGETS > 6
uniform LIDR_INDEX_SAMPLER uIndexTex6;
#endif
#if LIDR_INDEX_TARGETS > 7
uniform LIDR_INDEX_SAMPLER uIndexTex7;
#endif
