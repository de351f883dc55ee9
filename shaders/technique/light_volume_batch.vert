#version 120
// Light volumes in batches (pseudo-instancing, GL 2.1 has no instancing): the vertex buffer holds
// LIDR_BATCH copies of the volume mesh, each vertex tagged with its copy's slot; slot s draws light s of the
// batch from the uniform arrays. Copies are laid out in slot order, and GL blends and stencils in primitive
// order within a draw, so a batch draws its lights exactly in priority order, as one draw per light would.
attribute vec3 aPosition;
attribute float aSlot;
uniform mat4 uViewProj;
uniform mat4 uView;
uniform mat4 uProjection;
uniform vec4 uLights[LIDR_BATCH];                           // world centre, radius
uniform vec4 uCones[LIDR_BATCH];  // a spot's cone term as the shading takes it (world axis x scale, offset); (0, 0, 0, 1) for a point light
uniform vec4 uIndexColors[LIDR_BATCH * LIDR_DRAW_TARGETS];  // the light's value per target, bytes / 255
// 1.0 where the context has no depth clamp and a volume of the batch reaches past the far plane: vertices
// beyond it are pulled onto it (x, y and w untouched, so the footprint is unchanged); the pass then draws
// the batch without its depth pre-test.
uniform float uClampToFar;
#ifdef LIDR_SHADOWS
// LIDR_SHADOWS (a draw with shadow-casting lights): light s's first shadow-atlas tile in lane s mod 4 of
// entry s / 4 (-1: it casts none), a quarter of a uniform vector per light.
uniform vec4 uShadowTiles[(LIDR_BATCH + 3) / 4];
varying float vShadowTile;
#endif

varying vec4 vLightView;  // centre in view space, radius (the same at every vertex of a copy)
#ifdef LIDR_SPOT_CONES
varying vec4 vConeView;   // the cone term with its axis in view space (the view has no scale: dots are kept)
#endif
varying vec3 vViewPos;    // this point of the volume in view space: its direction is the pixel's eye ray
varying vec4 vColor0;
#if LIDR_DRAW_TARGETS > 1
varying vec4 vColor1;
#endif
#if LIDR_DRAW_TARGETS > 2
varying vec4 vColor2;
varying vec4 vColor3;
#endif

void main() {
    int slot = int(aSlot + 0.5);
    vec4 light = uLights[slot];
#ifdef LIDR_SCREEN_TILES
    gl_Position = uProjection * vec4(aPosition, 1.0);
    vViewPos = aPosition;  // a plane in view space: interpolated exactly along the pixel's ray
#else
    vec4 world = vec4(light.xyz + aPosition * light.w, 1.0);
    gl_Position = uViewProj * world;
    vViewPos = (uView * world).xyz;
    if (uClampToFar > 0.5 && gl_Position.w > 0.0) gl_Position.z = min(gl_Position.z, gl_Position.w);
#endif
    vLightView = vec4((uView * vec4(light.xyz, 1.0)).xyz, light.w);
#ifdef LIDR_SPOT_CONES
    vec4 cone = uCones[slot];
    vConeView = vec4((uView * vec4(cone.xyz, 0.0)).xyz, cone.w);
#endif
#ifdef LIDR_SHADOWS
    vec4 tiles = uShadowTiles[slot / 4];
    int lane = slot - (slot / 4) * 4;
    vShadowTile = lane == 0 ? tiles.x : (lane == 1 ? tiles.y : (lane == 2 ? tiles.z : tiles.w));
#endif
    int c = slot * LIDR_DRAW_TARGETS;
    vColor0 = uIndexColors[c];
#if LIDR_DRAW_TARGETS > 1
    vColor1 = uIndexColors[c + 1];
#endif
#if LIDR_DRAW_TARGETS > 2
    vColor2 = uIndexColors[c + 2];
    vColor3 = uIndexColors[c + 3];
#endif
}
