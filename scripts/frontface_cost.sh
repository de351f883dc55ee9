#!/usr/bin/env bash
# Measures what the front-face volume test costs against the back-face test on the default room: slots used
# per pixel and lights dropped, per budget. Writes a Markdown table to stdout (doc/msaa-transparency.md).
#   bash scripts/frontface_cost.sh [build-dir] [scheme]
set -euo pipefail
build="${1:-build}"
scheme="${2:-bitshift}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "| budget | volume test | mean slots / pixel | max slots | pixels marked > budget | dropped light-pixels | PSNR within budget (dB) |"
echo "|---|---|---|---|---|---|---|"
for budget in 1 2 4 8 16; do
  for test in backface frontface; do
    out="$tmp/$budget-$test"
    if ! "$build/demo/lidr-demo" --headless --frames 1 --scheme "$scheme" --budget "$budget" --volume-test "$test" \
         --transparency off --out "$out" >"$tmp/log" 2>&1; then
      echo "| $budget | $test | (not available: $(grep -o 'error: .*' "$tmp/log" | head -c 120)) | | | | |"
      continue
    fi
    python3 - "$out/summary.json" "$budget" "$test" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
l, e = s["lights"], s["error"]["pixels_within_budget"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {l['mean_slots_used']:.3f} | {l['max_slots_used']} | "
      f"{l['pixels_marked_over_budget']} | {l['dropped_light_pixels']} | {e['psnr_db']:.1f} |")
PY
  done
done
