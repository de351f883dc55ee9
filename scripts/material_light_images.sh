#!/usr/bin/env bash
# Regenerates the material and light model pictures of README.md and doc/scene-format.md (512x384, llvmpipe)
# with lidr-demo: the courtyard and the crate (default rig), a generated textured glTF (tests/make_glb.py) under
# the default rig, with --lights 1024, and with its own KHR_lights_punctual lights (candela, inverse square).
#   bash scripts/material_light_images.sh [build-dir]
set -euo pipefail
build="${1:-build}"
out="doc/images"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
demo="$build/demo/lidr-demo"
common=(--headless --width 512 --height 384 --frames 1)
python3 tests/make_glb.py "$tmp/textured.glb" --textured >/dev/null
python3 tests/make_glb.py "$tmp/textured-lights.glb" --textured --punctual >/dev/null
render() {  # NAME DEMO-ARGS...: the LIDR image, after checking it against the brute-force reference
    local name="$1"
    shift
    "$demo" "${common[@]}" "$@" --out "$tmp/$name" >"$tmp/$name.log"
    # nothing dropped; at most one 8-bit step (LIDR sums a pixel's lights in its lists' order)
    grep -q "dropped light-pixels 0," "$tmp/$name.log" && grep -Eq "whole image: max [01]," "$tmp/$name.log" ||
        { echo "$name: not the reference's image: $(grep -E '^(lights|error) ' "$tmp/$name.log")" >&2; exit 1; }
    echo "$name: $(grep '^error ' "$tmp/$name.log")"
    cp "$tmp/$name/lidr.png" "$out/$name.png"
}
render courtyard-lights-1024 --scene media/scenes/courtyard.gltf --lights 1024 --transparency off
render crate-default-rig --scene media/models/crate.obj
render textured-default-rig --scene "$tmp/textured.glb"
render textured-lights-1024 --scene "$tmp/textured.glb" --lights 1024
render textured-gltf-lights --scene "$tmp/textured-lights.glb"
echo "wrote 5 images to $out"
