#!/usr/bin/env bash
# Regenerates doc/images/viewer-model.png and doc/images/web-model.png: a generated .glb (tests/make_glb.py)
# dropped on lidr-viewer (Xvfb, llvmpipe), and the same file opened by the web page's URL query with 1024 lights
# (headless Chromium, SwiftShader). Needs the native build (lidr-viewer) and the web build (build-web/web).
#   bash scripts/model_screenshots.sh [build-dir] [web-build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}" web="${2:-build-web}/web"
tmp="$(mktemp -d)"
server_pid=""
cleanup() { [ -n "$server_pid" ] && kill "$server_pid" 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
python3 tests/make_glb.py "$tmp/model.glb" >/dev/null
sed -e "s|@MODEL@|$tmp/model.glb|" -e "s|@OUT@|$tmp|" viewer/doc_screenshot_model.script > "$tmp/shot.script"
xvfb-run -a -s "-screen 0 1280x1024x24" "$build/viewer/lidr-viewer" --width 1280 --height 720 --paused \
  --script "$tmp/shot.script" --out "$tmp" >/dev/null
cp "$tmp/viewer-model.png" doc/images/viewer-model.png

mkdir -p "$web/models"
cp "$tmp/model.glb" "$web/models/doc.glb"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server -b 127.0.0.1 -d "$web" "$port" >/dev/null 2>&1 &
server_pid=$!
sleep 1
chromium --headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader --use-angle=swiftshader \
  --disable-background-networking --disable-component-update --no-first-run --user-data-dir="$tmp/profile" \
  --window-size=1120,700 --virtual-time-budget=20000 --screenshot="$PWD/doc/images/web-model.png" \
  "http://127.0.0.1:$port/lidr_web.html?scene=models/doc.glb&lights=1024&mode=lidr" >/dev/null 2>&1
echo "wrote doc/images/viewer-model.png and doc/images/web-model.png"
