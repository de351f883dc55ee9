#!/usr/bin/env bash
# lidr's checks on a machine with a real GPU (headless EGL; no X server): the whole test suite on the GPU's
# driver, the [context] tests through the EGL device backend, the headless demo, and the full lidr-bench sweep
# (GPU timer queries). Speed is only measured by the bench; the tests assert images, indices and counts.
#   bash scripts/gpu_check.sh [OUT [PART]]   OUT default gpu-check; PART: all (default), tests (tests and demo),
#                                            bench; extra lidr-bench arguments in BENCH_ARGS
# TEST_ARGS: lidr-tests' test spec (default: every case); BENCH_SET: the lidr-bench selection (default --full;
# e.g. "--sweep peers" for issue 37's best-peer table). On a machine that is not Debian 12, pack the binaries
# with scripts/gpu_bundle.sh and set BIN to the bundle's bin/ after sourcing its --env.
# BIN: a folder holding lidr-tests, lidr-demo and lidr-bench (default: this checkout's build/). The tests read
# media/ and doc/ under the source folder they were built from (LIDR_SOURCE_DIR): run them from that path.
# Writes OUT/tests.log, OUT/tests-egl-device.log, OUT/demo/ (images, summary), OUT/bench/ (results.csv,
# passes.csv, results.json, summary.md) and OUT/environment.txt; exits non-zero if anything failed.
set -uo pipefail
out="$(realpath -m "${1:-gpu-check}")"  # relative to where the script was called from
part="${2:-all}"
[ -n "${BIN:-}" ] && BIN="$(realpath -m "$BIN")"
cd "$(dirname "$0")/.."
case "$part" in all|tests|bench) ;; *) echo "gpu_check.sh: PART is all, tests or bench, not '$part'" >&2; exit 2;; esac
if [ -n "${BIN:-}" ]; then
  tests="$BIN/lidr-tests" demo="$BIN/lidr-demo" bench="$BIN/lidr-bench"
else
  tests=build/tests/lidr-tests demo=build/demo/lidr-demo bench=build/bench/lidr-bench
fi
for b in "$tests" "$demo" "$bench"; do
  [ -x "$b" ] || { echo "gpu_check.sh: $b not found (build first, or set BIN)" >&2; exit 2; }
done
mkdir -p "$out"
status=0
{
  date -u
  uname -a
  command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv
  git rev-parse HEAD 2>/dev/null && git status --short 2>/dev/null | head -20
} >"$out/environment.txt" 2>&1

if [ "$part" != bench ]; then
  echo "gpu_check.sh: test suite (LIDR_CONTEXT=${LIDR_CONTEXT:-auto})"
  read -r -a spec <<<"${TEST_ARGS:-}"
  "$tests" --durations yes "${spec[@]}" >"$out/tests.log" 2>&1 || status=1
  grep -E "GL context:" -A2 "$out/tests.log" | head -3
  tail -2 "$out/tests.log"

  echo "gpu_check.sh: [context] tests through the EGL device backend"
  LIDR_CONTEXT=egl-device "$tests" "[context]" >"$out/tests-egl-device.log" 2>&1 || status=1
  tail -2 "$out/tests-egl-device.log"

  echo "gpu_check.sh: headless demo"
  mkdir -p "$out/demo"
  "$demo" --headless --out "$out/demo" >"$out/demo/stdout.txt" 2>&1 || status=1
  tail -3 "$out/demo/stdout.txt"
fi

if [ "$part" != tests ]; then
  read -r -a set <<<"${BENCH_SET:---full}"
  echo "gpu_check.sh: bench ${set[*]}"
  read -r -a extra <<<"${BENCH_ARGS:-}"  # words, no globbing
  "$bench" "${set[@]}" --no-progress --out "$out/bench" "${extra[@]}" || status=1
fi
exit $status
