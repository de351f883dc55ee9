#version 120
// The overlap probe counts pixels that pass its stencil test (an occlusion query); colour writes are off.
void main() {
    gl_FragColor = vec4(0.0);
}
