#!/usr/bin/env bash
# LIDR's default under MSAA on the real models (issue 43): lidr-demo renders each of media/'s scenes and BART's
# Robots (../shared/bart-robots, both light set-ups, t = 0) at 2x and 4x MSAA, transparency off and on, and prints
# per run the lights line (dropped light-pixels against every sample's surface) and the error line (against
# forward-brute with the same MSAA and transparency), one row each, then the worst of them.
#   bash scripts/msaa_models.sh [build-dir] [WIDTHxHEIGHT]       (default: build 1024x768)
# Under MESA_GL_VERSION_OVERRIDE=2.1 MESA_GLSL_VERSION_OVERRIDE=120 the same runs take the GL 2.1 moments.
# About 6 minutes on the 2-core VM (the BART runs' forward-brute references are most of it).
set -euo pipefail
build="${1:-build}"
size="${2:-1024x768}"
width="${size%x*}"
height="${size#*x}"
root="$(cd "$(dirname "$0")/.." && pwd)"
demo="$build/demo/lidr-demo"
[ -x "$demo" ] || { echo "msaa_models.sh: no lidr-demo at $demo (build first)" >&2; exit 2; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
rows=0 dropped=0 worst=999
for scene in "$root"/media/scenes/*.gltf "$root"/media/scenes/*.json "$root"/media/models/*.obj \
             bart-robots-many bart-robots-few; do
  for samples in 2 4; do
    for transparency in off on; do
      log="$("$demo" --scene "$scene" --msaa "$samples" --transparency "$transparency" --width "$width" \
             --height "$height" --frames 1 --out "$out" 2>&1)" || { echo "$log" >&2; exit 1; }
      lights="$(grep -E '^lights +visible' <<<"$log" | sed 's/^lights *//')"
      error="$(grep -E '^error ' <<<"$log" | sed 's/^error *//')"
      spans="$(grep -E '^lidr ' <<<"$log" | grep -o 'budget [0-9]*\|volume test [a-z-]* ([a-z]* spans' | tr '\n' ' ')"
      echo "$(basename "$scene") ${samples}x transparency $transparency | $lights | $error | $spans"
      rows=$((rows + 1))
      dropped=$((dropped + $(grep -o 'dropped light-pixels [0-9]*' <<<"$lights" | grep -o '[0-9]*$')))
      psnr="$(grep -o 'PSNR [0-9.]*' <<<"$error" | head -1 | grep -o '[0-9.]*$')"
      worst="$(python3 -c "print(min($worst, $psnr))")"
    done
  done
done
echo "$rows runs: $dropped dropped light-pixels in all, worst PSNR $worst dB"
