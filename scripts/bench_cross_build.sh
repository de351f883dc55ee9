#!/bin/bash
# The ten issue-12 scenes with LIDR's default configuration, two builds alternated three times (the data of its
# run is doc/results/cross-build/: NEW = 974ed21 in build/, OLD = 78c01eb, the commit before issue 25's first
# change, built in a worktree with `cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo && cmake --build build
# --target lidr-bench`; doc/experiments/2026-12-04-occluded-targets.md).
#   bash scripts/bench_cross_build.sh NEW_BUILD_DIR OLD_BUILD_DIR OUT_DIR
set -euo pipefail
new="$1" old="$2" out="$3"
S=room,overlap-1,overlap-2,overlap-4,overlap-8,overlap-16,many-1024-top,many-1024-fp,many-4096-top,many-4096-fp
for i in 1 2 3; do
  for b in new old; do
    if [ $b = new ]; then B="$new/bench/lidr-bench"; else B="$old/bench/lidr-bench"; fi
    "$B" --scenes $S --modes lidr --schemes auto --volume-tests sphere --transparency off --frames 5 --out "$out/$b$i" --no-plots
  done
done
