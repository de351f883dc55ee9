#!/usr/bin/env bash
# lidr set-up on Debian 12: installs what is missing (apt-get, as root), builds, then runs one job.
#   bash scripts/setup.sh demo   render the default scene headless into out/ (images + summary)
#   bash scripts/setup.sh test   run the whole test suite (llvmpipe, softpipe, GL 2.1 override, OpenGL ES 2.0, OSMesa,
#                                demo, viewer, examples, package), then the AddressSanitizer + UBSan build's subset
#                                and the fuzz smoke runs (clang), then the WebGL 1 page's test (as the web job)
#   bash scripts/setup.sh bench  the full lidr-bench sweep into doc/results/full/ (summary.md, linked from doc/benchmarks.md)
#   bash scripts/setup.sh web    the WebGL 1 page (emscripten) into build-web/web/, then its test in headless
#                                Chromium (CTest web.chromium; doc/web.md)
# Environment: BUILD_DIR (default build), JOBS (default: number of cores), OUT_DIR (default out),
#   SANITIZE_BUILD_DIR (default build-sanitize), SANITIZE=0 skips the sanitizer build and fuzz runs (test job),
#   WEB_BUILD_DIR (default build-web), WEB=0 skips the WebGL 1 page and its browser test (test job).
set -euo pipefail
cd "$(dirname "$0")/.."

# Each step's wall time (and, for the test job, each CTest entry's against its budget: scripts/ci_times.cmake),
# printed when the job ends, failed or not.
times_dir="$(mktemp -d)"
ctest_runs=()
step() {  # step NAME COMMAND...: runs COMMAND, recording its seconds under NAME
  local name="$1" start=$SECONDS rc=0
  shift
  "$@" || rc=$?
  printf '%s\t%s\n' "$name" "$((SECONDS - start))" >>"$times_dir/steps"
  return $rc
}
ctest_step() {  # ctest_step NAME BUILD_DIR CTEST_ARGS...: a step that runs CTest in BUILD_DIR, its entries kept
  local name="$1" dir="$2" index=$((${#ctest_runs[@]} / 2)) start=$SECONDS rc=0  # runs hold two entries each
  shift 2
  ctest --test-dir "$dir" --show-only=json-v1 >"$times_dir/ctest-$index.json" 2>/dev/null || true
  ctest --test-dir "$dir" "$@" 2>&1 | tee "$times_dir/ctest-$index.log" || rc=$?
  ctest_runs+=("$times_dir/ctest-$index.log" "$times_dir/ctest-$index.json")
  printf '%s\t%s\t%s\n' "$name" "$((SECONDS - start))" "$index" >>"$times_dir/steps"
  return $rc
}
print_times() {
  local runs
  runs="$(IFS=';'; echo "${ctest_runs[*]:-}")"
  cmake -DSTEPS="$times_dir/steps" -DRUNS="$runs" -DTOTAL="$SECONDS" -DLIMIT="${CI_TIME_AIM:-1800}" \
    -P scripts/ci_times.cmake || true
  rm -rf "$times_dir"
}
trap print_times EXIT

job="${1:-}"
case "$job" in
  demo|test|bench|web) ;;
  *) echo "usage: bash scripts/setup.sh demo|test|bench|web" >&2; exit 2 ;;
esac

# Debian 12 packages only; nothing is downloaded at build time.
# emscripten 3.1.6 ships its system libraries prebuilt in a frozen cache (EM_CACHE stays unset); node-acorn
# comes with it (its optimising link steps need NODE_PATH=/usr/share/nodejs when Node.js is not Debian's).
# The page's model check compares it with lidr-web-native-frame, built natively: the library's packages too.
web_packages=(cmake emscripten chromium python3
  build-essential pkg-config libegl-dev libegl1-mesa-dev libgl-dev libgl1-mesa-dri libglew-dev libglm-dev
  libstb-dev libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev)
if [ "$job" = web ]; then
  packages=("${web_packages[@]}")
else
packages=(
  build-essential cmake pkg-config
  libegl-dev libegl1-mesa-dev libgl-dev libgl1-mesa-dri libglew-dev libglm-dev libglfw3-dev
  libstb-dev catch2 libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev
  gnuplot-nox
  libimgui-dev xvfb xauth
  clang libclang-rt-14-dev
)
if [ "$job" = test ] && [ "${WEB:-1}" != 0 ]; then packages+=("${web_packages[@]}"); fi
fi
# Optional: OSMesa (lidr::lidr_osmesa, suite.osmesa) only where the distribution still has it (not Mesa 25.1+).
optional=(libosmesa6-dev)
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
for p in "${packages[@]}"; do
  installed "$p" || missing+=("$p")
done
for p in "${optional[@]}"; do
  installed "$p" || ! apt-cache show "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  if [ "$(id -u)" != 0 ]; then
    echo "setup: these Debian packages are missing and installing them needs root: ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  step "install packages" bash -c 'apt-get update -qq && apt-get install -y -qq --no-install-recommends "$@" >/dev/null' \
    apt "${missing[@]}"
fi

jobs="${JOBS:-$(nproc)}"
# The native build: -O2 with -g1 debug info (functions and line tables: what a backtrace needs, no local variables):
# a third less compile time than RelWithDebInfo's -g (doc/stability.md, "Budgets").
native_config=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
# The page and its test only: the library's web layers, web/lidr_web.cpp, CTest web.chromium (doc/web.md).
web_build_and_test() {
  local web_build="${WEB_BUILD_DIR:-build-web}" native_build="${BUILD_DIR:-build}"
  export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
  # lidr-web-native-frame: the native frames web.chromium's model check compares the page's with. An existing
  # native build folder is used as it is configured; a new one builds the library and that tool alone.
  if [ ! -f "$native_build/CMakeCache.txt" ]; then
    cmake -S . -B "$native_build" "${native_config[@]}" -DLIDR_BUILD_TESTS=OFF -DLIDR_BUILD_DEMO=OFF \
      -DLIDR_BUILD_EXAMPLES=OFF >/dev/null
  fi
  step "web: lidr-web-native-frame" cmake --build "$native_build" -j "$jobs" --target lidr-web-native-frame
  emcmake cmake -S . -B "$web_build" -DCMAKE_BUILD_TYPE=Release -DLIDR_WEB=ON \
    -DLIDR_NATIVE_FRAME_TOOL="$(cd "$native_build" && pwd)/web/lidr-web-native-frame" >/dev/null
  step "web: build ($web_build/)" cmake --build "$web_build" -j "$jobs"
  ctest_step "web: tests ($web_build/)" "$web_build" --output-on-failure --no-tests=error
}
if [ "$job" = web ]; then
  web_build_and_test
  exit 0
fi

build="${BUILD_DIR:-build}"
cmake -S . -B "$build" "${native_config[@]}" >/dev/null
step "build ($build/)" cmake --build "$build" -j "$jobs"

case "$job" in
  demo)
    "$build/demo/lidr-demo" --headless --out "${OUT_DIR:-out}"
    ;;
  bench)
    BUILD_DIR="$build" bash scripts/bench.sh
    ;;
  test)
    ctest_step "tests ($build/)" "$build" --output-on-failure -j "$jobs"
    if [ "${SANITIZE:-1}" != 0 ]; then
      # A second build with AddressSanitizer + UBSan and the libFuzzer harnesses (clang): sanitize.cpu,
      # sanitize.gl (a GL subset, tests/CMakeLists.txt) and fuzz.* smoke runs. doc/stability.md says why and how long.
      sanitize_build="${SANITIZE_BUILD_DIR:-build-sanitize}"
      # -O1 with line tables only (what the sanitizers' reports need): a fifth less compile time than -O2 -g.
      cmake -S . -B "$sanitize_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
        -DCMAKE_CXX_COMPILER=clang++ "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" \
        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" -DLIDR_SANITIZE=address,undefined -DLIDR_BUILD_FUZZERS=ON \
        -DLIDR_BUILD_DEMO=OFF -DLIDR_BUILD_EXAMPLES=OFF -DLIDR_WITH_OSMESA=OFF >/dev/null
      step "sanitizer build ($sanitize_build/)" cmake --build "$sanitize_build" -j "$jobs"
      ctest_step "sanitizer tests ($sanitize_build/)" "$sanitize_build" --output-on-failure -j "$jobs"
    fi
    if [ "${WEB:-1}" != 0 ]; then
      web_build_and_test
    fi
    ;;
esac
