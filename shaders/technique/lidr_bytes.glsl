// Exact bytes from RGBA8 texel reads, in plain float arithmetic that holds in fp16, fp24 and fp32.
// floor(x * 255.0 + 0.5) fails in fp16 near 1.0 (255 needs 8 integer bits, leaving 3 for the fraction, and
// the product and the sum each round). Instead the byte is found bit by bit, most significant first: compare
// the residual with a threshold, subtract the bit's value. Every constant is exactly representable in fp16
// (so it is the same number in every precision); every subtraction is exact (Sterbenz: the residual lies
// within [Y/2, 2Y] of the value Y it loses); comparisons are exact. The decision for a read x is therefore
// the real-number comparison of x with thresholds that all lie between (b + 0.45)/255 and (b + 0.55)/255:
// any read within +-0.45 of a step (the worst margin is 0.046 step) gives back the exact byte. The CPU model
// (lidr/base/shader_float.h) runs the same steps in emulated precision; tests prove it exhaustively.
//   bit 7: threshold 1/2 (= 127.5/255),   value 257/512   (~128/255)
//   bit j: threshold ~ (2^j - 0.5)/255,   value 257/2^(16-j) (~2^j/255)
// That is for fp16 fragments (OpenGL ES mediump: LIDR_FRAGMENT_FP16). With at least fp24 (every desktop GL 2.x
// part: fp24 on ATI R300-R500, fp32 elsewhere) the plain rounding is exact for the same reads and costs two
// operations instead of 24: x * 255 errs by under 2^-9 of a step in fp24 and +0.5 adds no rounding that could
// cross an integer (tests: "lidrBytes, rounded path").
#ifndef LIDR_FRAGMENT_FP16
vec4 lidrBytes(vec4 x) {
    return floor(x * 255.0 + 0.5);
}
#else
vec4 lidrBytes(vec4 x) {
    vec4 b = vec4(0.0), bit;
    bit = step(vec4(0.5), x);                  x -= bit * 0.501953125;           b += bit * 128.0;
    bit = step(vec4(0.2490234375), x);         x -= bit * 0.2509765625;          b += bit * 64.0;
    bit = step(vec4(0.12353515625), x);        x -= bit * 0.12548828125;         b += bit * 32.0;
    bit = step(vec4(0.060791015625), x);       x -= bit * 0.062744140625;        b += bit * 16.0;
    bit = step(vec4(0.0294189453125), x);      x -= bit * 0.0313720703125;       b += bit * 8.0;
    bit = step(vec4(0.01372528076171875), x);  x -= bit * 0.01568603515625;      b += bit * 4.0;
    bit = step(vec4(0.00588226318359375), x);  x -= bit * 0.007843017578125;     b += bit * 2.0;
    bit = step(vec4(0.00196075439453125), x);                                    b += bit;
    return b;
}
#endif
