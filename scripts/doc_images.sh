#!/usr/bin/env bash
# Regenerates the images in doc/images/ with lidr-demo (llvmpipe): the default room at 640x480, and the material
# and light model pictures of doc/demo.md and doc/scene-format.md at 512x384: the courtyard and the crate (default
# rig), a generated textured glTF (tests/make_glb.py) under the default rig, with --lights 1024, and with its own
# KHR_lights_punctual lights (candela, inverse square); models get the default environment light (issue 39), and the
# metal showcase is drawn without and with it; README's picture of the technique (technique.png: the default
# room's LIDR frame, its decoded index lists and the lights touching each pixel, side by side).
#   bash scripts/doc_images.sh [build-dir]
set -euo pipefail
source "$(dirname "$0")/doc_images_env.sh"  # build, demo, out (doc/images), tmp
side_by_side() {  # OUT IN...: the PNGs (same height) next to each other, left to right
    python3 - "$@" <<'PY'
import sys
sys.path.insert(0, "web")
from run_chromium_check import read_png, write_png
images = [read_png(p) for p in sys.argv[2:]]
h = images[0][1]
assert all(i[1] == h for i in images), "side_by_side: the images differ in height"
rows = (b"".join(rgba[y * w * 4:(y + 1) * w * 4] for w, _, rgba in images) for y in range(h))
write_png(sys.argv[1], sum(i[0] for i in images), h, b"".join(rows))
PY
}
common=(--headless --width 640 --height 480 --frames 1)
"$demo" "${common[@]}" --volume-test backface --transparency off --out "$tmp/back" >/dev/null
"$demo" "${common[@]}" --volume-test frontface --out "$tmp/front" >/dev/null
"$demo" "${common[@]}" --volume-test frontface --msaa 4 --out "$tmp/msaa" >/dev/null
cp "$tmp/back/lidr.png" "$out/room-backface-opaque.png"
cp "$tmp/back/marked.png" "$out/room-backface-marked.png"
cp "$tmp/front/marked.png" "$out/room-frontface-marked.png"
cp "$tmp/front/lidr.png" "$out/room-frontface-glass.png"
cp "$tmp/msaa/lidr.png" "$out/room-msaa4-glass.png"
cp "$tmp/msaa/difference.png" "$out/room-msaa4-glass-difference.png"
model=(--headless --width 512 --height 384 --frames 1)
python3 tests/make_glb.py "$tmp/textured.glb" --textured >/dev/null
python3 tests/make_glb.py "$tmp/textured-lights.glb" --textured --punctual >/dev/null
render() {  # NAME DEMO-ARGS...: the LIDR image, after checking it against the brute-force reference
    local name="$1"
    shift
    "$demo" "${model[@]}" "$@" --out "$tmp/$name" >"$tmp/$name.log"
    # nothing dropped; at most one 8-bit step (the courtyard's few, doc/colour.md "Lights for any model")
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
# Shadows (doc/shadows.md): the pillar hall with its own casters ("shadow": true) and with shadows off, in tiled
# forward, each checked equal to the reference rendered with the same shadows.
for shadows in scene off; do
    "$demo" "${model[@]}" --scene media/scenes/pillar-hall-shadows.json --mode tiled --shadows "$shadows" \
        --out "$tmp/pillars-$shadows" >"$tmp/pillars-$shadows.log"
    grep -Eq "^error +max [01]," "$tmp/pillars-$shadows.log" ||
        { echo "pillar-hall --shadows $shadows: not the reference's image: $(grep '^error ' "$tmp/pillars-$shadows.log")" >&2; exit 1; }
done
cp "$tmp/pillars-scene/tiled.png" "$out/pillar-hall-shadows.png"
cp "$tmp/pillars-off/tiled.png" "$out/pillar-hall-no-shadows.png"
# The environment light (doc/colour.md, "Environment light"): the metal showcase (tests/make_glb.py --metal-showcase)
# under the default rig without an environment (--environment none) and with the default one, side by side.
python3 tests/make_glb.py "$tmp/helmet.glb" --metal-showcase >/dev/null
render environment-helmet-none --scene "$tmp/helmet.glb" --environment none
render environment-helmet-default --scene "$tmp/helmet.glb"
side_by_side "$out/environment-helmet.png" "$out/environment-helmet-none.png" "$out/environment-helmet-default.png"
rm "$out/environment-helmet-none.png" "$out/environment-helmet-default.png"
# README's picture: the default room as lidr-demo's default run renders it (the automatic configuration), at
# 480x360: the frame, the decoded index lists (one colour per light index) and the overlap heat map (lights whose
# sphere holds each pixel's surface, CPU truth), checked equal to the reference.
"$demo" --headless --width 480 --height 360 --frames 1 --out "$tmp/technique" >"$tmp/technique.log"
grep -q "dropped light-pixels 0," "$tmp/technique.log" && grep -Eq "whole image: max 0," "$tmp/technique.log" ||
    { echo "technique: not the reference's image: $(grep -E '^(lights|error) ' "$tmp/technique.log")" >&2; exit 1; }
side_by_side "$out/technique.png" "$tmp/technique/lidr.png" "$tmp/technique/index_lists.png" "$tmp/technique/overlap.png"
echo "wrote $(ls "$out" | wc -l) images to $out"
