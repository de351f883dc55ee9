#version 120
// The light-volume pass's pixel-list geometry (tests/pixel_list_geometry.h): this draw stands for step j of
// every pixel's index list. A pixel whose list has no j-th entry is not marked (discard: no colour, no stencil
// operation); one that has it writes the colours the scheme gives that index, from a table filled from the
// scheme's own colour callback. Blend and stencil state are the scheme's draw's own. Clear depth to 0.5.
uniform sampler2D uStepIndices;  // R = index low byte, G = high byte (0: no fragment); B = 1: a decoy
uniform sampler2D uColorTable;   // target t, index i: texel (i mod 256, t * rowsPerTarget + i / 256)
uniform vec2 uInvTargetSize;
uniform float uTableRowsPerTarget;
uniform float uTableHeight;

void main() {
    vec4 step = texture2D(uStepIndices, gl_FragCoord.xy * uInvTargetSize);
    float low = floor(step.r * 255.0 + 0.5), high = floor(step.g * 255.0 + 0.5);
    if (low + high < 0.5) discard;
    // A decoy is a light whose volume covers the pixel but lies in front of the surface: its fragment fails
    // the volume test's depth test (GEQUAL against the cleared 0.5). Real entries pass it.
    gl_FragDepth = step.b > 0.5 ? 0.25 : 1.0;
    for (int t = 0; t < LIDR_DRAW_TARGETS; ++t) {
        vec2 uv = vec2((low + 0.5) / 256.0, (float(t) * uTableRowsPerTarget + high + 0.5) / uTableHeight);
        gl_FragData[t] = texture2D(uColorTable, uv);
    }
}
