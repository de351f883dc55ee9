#!/usr/bin/env bash
# Regenerates the images in doc/images/ (default room, 640x480, llvmpipe) with lidr-demo.
#   bash scripts/doc_images.sh [build-dir]
set -euo pipefail
build="${1:-build}"
out="doc/images"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
demo="$build/demo/lidr-demo"
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
echo "wrote $(ls "$out" | wc -l) images to $out"
