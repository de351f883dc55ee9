// Emulated depth precision (LidrOptions::emulatedDepthBits): the window depth rounded to the nearest of the
// LIDR_DEPTH_STEPS + 1 levels a DEPTH_COMPONENT16 buffer holds (LIDR_DEPTH_STEPS = 65535.0). Distinct levels
// stay distinct and in order in the 24-bit buffer (they lie 256 of its steps apart), so every depth test, and the
// depth copy the sphere tests read, sees what a 16-bit buffer would. Every pass that writes or tests depth calls
// this, with the same vertex shader, so the forward pass's EQUAL test still matches the pre-pass.
void lidrWriteDepth() {
    gl_FragDepth = floor(gl_FragCoord.z * LIDR_DEPTH_STEPS + 0.5) / LIDR_DEPTH_STEPS;
}
