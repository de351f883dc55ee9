#version 120
// DepthSpanPass::writeCentreDepth (sphere-span with the samples' distances): sample 0's shaded point as the pixel's
// single-sample depth, the "centre" surface the sphere tests, the tiles and the evaluation read, written by one
// full-screen pass instead of a second geometry pass; nothing (the cleared far depth) where sample 0 has no surface.
// Compiled as GLSL 1.50 (perSampleGlsl150).
uniform sampler2DMS uSampleDistances;  // per sample, the view distance of the point it shades (0: none)
uniform vec2 uDepthToDistance;         // window depth d -> view distance x / (d + y); so d = x / distance - y

void main() {
    float x = texelFetch(uSampleDistances, ivec2(gl_FragCoord.xy), 0).r;
    if (x <= 0.0) discard;
    gl_FragDepth = clamp(uDepthToDistance.x / x - uDepthToDistance.y, 0.0, 1.0);
}
