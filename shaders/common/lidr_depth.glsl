// The fragment's depth as the depth buffer stores it. Every LIDR fragment shader that writes or tests depth
// calls lidrWriteDepth() first: at the buffer's own precision (this file) it does nothing; with
// LidrOptions::emulatedDepthBits the include is lidr_depth_emulated.glsl instead.
void lidrWriteDepth() {}
