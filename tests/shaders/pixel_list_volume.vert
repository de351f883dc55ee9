#version 120
// The light-volume pass's pixel-list geometry (tests/pixel_list_geometry.h): a full-target quad instead of a
// light volume. Wound clockwise, so the volume test sees a back face; the fragment shader sets the depth.
attribute vec3 aPosition;

void main() {
    gl_Position = vec4(aPosition.xy, 0.0, 1.0);
}
