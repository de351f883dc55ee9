#!/usr/bin/env bash
# The cone test in pictures (doc/architecture.md, "Light types"): the lamp street's lights per pixel as the
# volume pass marks them, spot lights indexed by their cones (the sphere test) against the same lights as
# points (their bounding spheres), side by side, and the lit frame. lidr-demo at 512x384 on the current context.
#   bash scripts/spot_cone_images.sh [build-dir]
set -euo pipefail
source "$(dirname "$0")/doc_images_env.sh"  # build, demo, out (doc/images), tmp
scene="media/scenes/lamp-street.json"
# The same street with every spot light a point light of the same position, range and colour.
python3 - "$scene" "$tmp/lamp-street-points.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
for light in scene["lights"]:
    if light.get("type") == "spot":
        for key in ("type", "direction", "inner_cone_angle", "outer_cone_angle"):
            light.pop(key, None)
json.dump(scene, open(sys.argv[2], "w"), indent=1)
PY
# One fixed budget, so both heat maps share one colour scale (overlapHeatMap colours a count against the budget).
common=(--headless --width 512 --height 384 --frames 1 --volume-test sphere --scheme bitshift --budget 8)
"$demo" "${common[@]}" --scene "$scene" --out "$tmp/cones" | grep -E '^(lidr|lights) '
"$demo" "${common[@]}" --scene "$tmp/lamp-street-points.json" --out "$tmp/spheres" | grep -E '^(lidr|lights) '
cp "$tmp/cones/marked.png" "$out/lamp-street-marked-cones.png"
cp "$tmp/spheres/marked.png" "$out/lamp-street-marked-spheres.png"
cp "$tmp/cones/lidr.png" "$out/lamp-street-lit.png"
echo "wrote lamp-street-{marked-cones,marked-spheres,lit}.png to $out"
