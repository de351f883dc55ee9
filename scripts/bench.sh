#!/usr/bin/env bash
# Reproduces doc/benchmarks.md: builds lidr (Release-with-debug-info), runs the full lidr-bench sweep into
# doc/bench/ (results.csv, passes.csv, results.json, summary.md, plots/*.png) and splices summary.md into
# doc/benchmarks.md between its "lidr-bench summary" markers. Extra arguments go to lidr-bench (e.g.
# --frames 5). Environment: BUILD_DIR (default build), JOBS (default 2), OUT (default doc/bench).
# SWEEP=lights,triangles (or one of them) runs only those scaling sweeps (--sweep) into OUT (default then
# doc/bench-sweeps) and splices nothing: `SWEEP=lights bash scripts/bench.sh`.
# Measure on an otherwise idle machine: the summary records the load average before and after.
set -euo pipefail
cd "$(dirname "$0")/.."

build="${BUILD_DIR:-build}"
sweep="${SWEEP:-}"
if [ -n "$sweep" ]; then out="${OUT:-doc/bench-sweeps}"; else out="${OUT:-doc/bench}"; fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j "${JOBS:-2}" --target lidr-bench
command -v gnuplot >/dev/null || echo "bench.sh: gnuplot is not installed (Debian: gnuplot-nox); CSV/JSON/tables only" >&2

rm -rf "$out"
if [ -n "$sweep" ]; then
  LIDR_CONTEXT="${LIDR_CONTEXT:-egl}" "$build/bench/lidr-bench" --sweep "$sweep" --out "$out" "$@"
  echo "bench.sh: the $sweep sweep(s) are in $out (summary.md, plots/lights_time.png, plots/triangles_time.png)"
  exit 0
fi
LIDR_CONTEXT="${LIDR_CONTEXT:-egl}" "$build/bench/lidr-bench" --full --out "$out" "$@"

doc=doc/benchmarks.md
begin='<!-- lidr-bench summary: begin (scripts/bench.sh writes this part) -->'
end='<!-- lidr-bench summary: end -->'
if [ "$out" = doc/bench ] && grep -qF "$begin" "$doc"; then
  # Headings one level down, plot links relative to doc/.
  summary="$(sed -e 's/^#/##/' -e 's|](plots/|](bench/plots/|g' "$out/summary.md")"
  awk -v begin="$begin" -v end="$end" -v summary="$summary" '
    $0 == begin { print; print summary; skip = 1; next }
    $0 == end { skip = 0 }
    !skip { print }' "$doc" > "$doc.tmp"
  mv "$doc.tmp" "$doc"
  echo "bench.sh: $doc updated from $out/summary.md"
fi
