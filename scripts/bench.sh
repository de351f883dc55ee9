#!/usr/bin/env bash
# The full lidr-bench sweep behind doc/benchmarks.md: builds lidr (Release-with-debug-info) and runs
# `lidr-bench --full` into doc/results/full/ (summary.md: the tables and plot links; results.csv, passes.csv,
# results.json, plots/*.png and their gnuplot scripts). doc/benchmarks.md and doc/results.md link that summary.md;
# nothing is spliced into a page. Extra arguments go to lidr-bench (e.g. --frames 5). Environment: BUILD_DIR
# (default build), JOBS (default 2), OUT (default doc/results/full).
# SWEEP=lights,triangles (or one of them) runs only those scaling sweeps (--sweep) into OUT (default then
# doc/results/sweeps): `SWEEP=lights bash scripts/bench.sh`.
# Measure on an otherwise idle machine: the summary records the load average before and after.
set -euo pipefail
cd "$(dirname "$0")/.."

build="${BUILD_DIR:-build}"
sweep="${SWEEP:-}"
if [ -n "$sweep" ]; then out="${OUT:-doc/results/sweeps}"; else out="${OUT:-doc/results/full}"; fi
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
echo "bench.sh: the full run's tables are in $out/summary.md (linked from doc/benchmarks.md and doc/results.md)"
