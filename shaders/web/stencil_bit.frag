#version 120
// The web page's stencil read-back (web/stencil_readback.cpp): one stencil bit's value, added where it is set.
uniform float uValue;

void main() {
    gl_FragColor = vec4(uValue);
}
