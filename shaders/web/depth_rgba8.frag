#version 120
// The web page's depth read-back (web/depth_readback.cpp): WebGL 1 cannot read depth with glReadPixels, so the
// scene is drawn again with geometry.vert (invariant position: the same depth as the pre-pass) and each
// fragment writes its window depth as a 24-bit number in R, G, B (high byte first). Needs fp32 fragment floats.
void main() {
    float v = min(floor(gl_FragCoord.z * 16777215.0 + 0.5), 16777215.0);  // 16777215.5 rounds to 2^24 in fp32
    float r = floor(v / 65536.0);
    float rest = v - r * 65536.0;
    float g = floor(rest / 256.0);
    float b = rest - g * 256.0;
    gl_FragColor = vec4(r, g, b, 255.0) / 255.0;
}
