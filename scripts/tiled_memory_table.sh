#!/usr/bin/env bash
# Prints doc/tiled.md's memory table: the tiled mode's per-frame light data for the default room at t = 0,
# per resolution and tile size, as lidr-demo --mode tiled reports it in summary.json (headless, EGL).
# Usage: bash scripts/tiled_memory_table.sh [build-dir]   (default: build)
set -euo pipefail
demo="${1:-build}/demo/lidr-demo"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "| resolution | tile | tiles | grids (2 x RGBA8) | list entries (opaque + transparent) | list texture (LA8) | depth reduction (float32) | depth reduction (packed RGBA8) |"
echo "|---|---|---|---|---|---|---|---|"
for res in 1024x768 1280x720 1920x1080 2560x1440; do
  for tile in 16 32 64; do
    w=${res%x*}; h=${res#*x}
    LIDR_CONTEXT=egl "$demo" --headless --no-reference --frames 1 --mode tiled --width "$w" --height "$h" \
      --tile-size "$tile" --out "$out/float" >/dev/null
    LIDR_CONTEXT=egl "$demo" --headless --no-reference --frames 1 --mode tiled --width "$w" --height "$h" \
      --tile-size "$tile" --packed-depth --out "$out/packed" >/dev/null
    python3 - "$res" "$tile" "$out" <<'PY'
import json, sys
res, tile, out = sys.argv[1], sys.argv[2], sys.argv[3]
f = json.load(open(f"{out}/float/summary.json"))["tiled"]
p = json.load(open(f"{out}/packed/summary.json"))["tiled"]
size = lambda b: f"{b / 1024:,.1f} KiB" if b < 1048576 else f"{b / 1048576:,.2f} MiB"
print(f"| {res} | {tile} | {f['tiles_x']}x{f['tiles_y']} | {size(f['grid_bytes'])} | "
      f"{f['opaque_entries']:,} + {f['transparent_entries']:,} | {size(f['list_bytes'])} | "
      f"{size(f['depth_reduction_bytes'])} | {size(p['depth_reduction_bytes'])} |")
PY
  done
done
