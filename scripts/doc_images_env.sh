# Sourced (not run) by the scripts that write doc/images/ (doc_images.sh, spot_cone_images.sh), with their
# arguments: sets `build` (the first argument, default build), `demo` (lidr-demo in it), `out` (doc/images,
# created) and `tmp` (a scratch folder, removed when the script exits).
build="${1:-build}"
out="doc/images"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
demo="$build/demo/lidr-demo"
