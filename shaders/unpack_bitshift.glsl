// Unpack for the CONSTANT_COLOR bit-shift scheme. Each channel of uIndexTex0 holds up to 8/k k-bit groups,
// the most recently drawn light's group in the top bits. Channel c holds bits [c*k, c*k + k) of the index.
// Arithmetic: bytes are rebuilt as integers with floor(x * 255 + 0.5), which is exact for any read within
// +-0.5 of a step (the paper's ceil(x * 254.5) tolerates low reads only); after that every value is an
// integer below 256, exact in fp16 and up. No integer or bit operations: GLSL 1.20.
//   LIDR_SLOTS            lights per pixel (the stencil never lets more in)
//   LIDR_GROUP_SCALE      2^(8-k): dividing by it takes the top k bits
//   LIDR_GROUP_VALUES     2^k: multiplying by it shifts the remaining bits up by k
//   LIDR_CHANNEL_WEIGHTS  vec4(1, 2^k, 2^2k, 2^3k), zero for unused channels
#define LIDR_NULL_ENDS_LIST 1

uniform LIDR_INDEX_SAMPLER uIndexTex0;
vec4 lidrPacked;  // bytes not yet unpacked, as integers

void lidrUnpackBegin(vec2 uv) {
    lidrPacked = floor(LIDR_FETCH_INDEX(uIndexTex0, uv) * 255.0 + 0.5);
}

float lidrUnpackNext() {
    vec4 top = floor(lidrPacked * (1.0 / LIDR_GROUP_SCALE));
    lidrPacked = (lidrPacked - top * LIDR_GROUP_SCALE) * LIDR_GROUP_VALUES;
    return dot(top, LIDR_CHANNEL_WEIGHTS);
}
