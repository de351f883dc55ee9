#!/usr/bin/env bash
# Packs this machine's lidr-tests, lidr-demo and lidr-bench with the shared libraries they load (Debian 12's
# glvnd, GLEW, GLFW, stb, tinyobjloader, X libraries) into one folder, for a machine with a GPU whose image is not
# Debian 12 (the device tool's NVIDIA machines). There, scripts/gpu_check.sh runs them with BIN=FOLDER/bin:
#   bash scripts/gpu_bundle.sh [BUILD [FOLDER]]        # here; default build and .gpu (ignored by .gitignore)
#   BUNDLE=FOLDER source scripts/gpu_bundle.sh --env     # there: LD_LIBRARY_PATH, NVIDIA's EGL vendor file
# glibc stays the machine's own (the binaries need 2.34); Debian's libstdc++ (needs glibc 2.36) is packed apart in
# FOLDER/lib-cxx and added only where the machine's own libstdc++ lacks what the binaries need.
if [ "${1:-}" = "--env" ]; then
  b="$(realpath "${BUNDLE:-.gpu}")"
  export LD_LIBRARY_PATH="$b/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  if ! "$b/bin/lidr-bench" --help >/dev/null 2>&1; then export LD_LIBRARY_PATH="$b/lib-cxx:$LD_LIBRARY_PATH"; fi
  for f in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
    [ -f "$f" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$f" && break
  done
  return 0 2>/dev/null || exit 0
fi
set -euo pipefail
build="${1:-build}"
out="${2:-.gpu}"
bins=("$build/tests/lidr-tests" "$build/demo/lidr-demo" "$build/bench/lidr-bench")
for b in "${bins[@]}"; do [ -x "$b" ] || { echo "gpu_bundle.sh: $b not found (build first)" >&2; exit 2; }; done
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/lib-cxx"
cp "${bins[@]}" "$out/bin/"
# Every library ldd resolves, but glibc's own (the machine's must serve its kernel and loader).
ldd "${bins[@]}" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | sort -u | while read -r name path; do
  case "$name" in
    libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|ld-linux*) ;;
    libstdc++.so.*|libgcc_s.so.*) cp -L "$path" "$out/lib-cxx/$name" ;;
    *) cp -L "$path" "$out/lib/$name" ;;
  esac
done
strip --strip-debug "$out"/bin/* "$out"/lib/* "$out"/lib-cxx/*  # the device tool carries 64 MiB
du -sh "$out"
