#!/usr/bin/env bash
# Instructions per pass of one frame, deterministic (llvmpipe on the calling thread, no timing noise):
# valgrind's callgrind runs lidr-demo with the CPU timing method, whose pass boundaries dump callgrind's counts
# (lidr/gl/frame_timer.cpp); this prints the last frame's instructions per pass and their sum.
#   bash scripts/callgrind_passes.sh [build-dir] -- LIDR-DEMO-ARGUMENTS...
# e.g. bash scripts/callgrind_passes.sh build -- --scene hall-255 --width 512 --height 384 --mode lidr
# Needs valgrind (Debian: valgrind, which also brings the callgrind.h the build looks for). Slow: a frame of
# the hall at 512x384 takes a few minutes.
set -euo pipefail
build="${1:-build}"
shift || true
[ "${1:-}" = "--" ] && shift
command -v valgrind >/dev/null || { echo "callgrind_passes.sh: valgrind is not installed (Debian: valgrind)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
LP_NUM_THREADS=0 LIDR_CONTEXT="${LIDR_CONTEXT:-egl}" valgrind --tool=callgrind --smc-check=all --dump-instr=no \
  --callgrind-out-file="$tmp/cg.out" "$build/demo/lidr-demo" --headless --no-reference --timer cpu --frames 2 \
  --out "$tmp/demo" "$@" >"$tmp/log" 2>&1 || { cat "$tmp/log" >&2; exit 1; }
python3 - "$tmp" <<'PY'
import glob, os, re, sys
last = {}  # pass -> instructions of its last dump (the second frame)
order = []
for f in sorted(glob.glob(os.path.join(sys.argv[1], "cg.out*")), key=lambda p: int((re.findall(r"\.(\d+)$", p) or [10**9])[0])):
    desc, total = None, None
    for line in open(f, "rb"):
        line = line.decode("utf-8", "replace")
        if line.startswith("desc: Trigger: Client Request: lidr-pass "):
            desc = line.split("lidr-pass ", 1)[1].strip()
        elif line.startswith("summary:") or line.startswith("totals:"):
            total = int(line.split()[1])
    if desc and total is not None:
        if desc not in last: order.append(desc)
        last[desc] = total
print("| pass | instructions (M) |")
print("|---|---|")
for d in order: print(f"| {d} | {last[d] / 1e6:.1f} |")
print(f"| **frame (sum)** | **{sum(last.values()) / 1e6:.1f}** |")
PY
