#version 120
// Deferred-Stencil's marking pass: the light volume's back faces set the stencil where the surface lies in front of
// them; colour is masked, so nothing is computed here (the light's shader runs in the front-face pass).
void main() {
    gl_FragColor = vec4(0.0);
}
