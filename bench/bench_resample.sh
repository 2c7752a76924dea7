#!/usr/bin/env bash
# Times `rotinterp resample` of a generated 100 000-frame, 31-joint BVH against
# assimp's own import of the same file, in the same run (bench/bench_resample.cpp),
# then the command line end to end on the same file.
# Usage: bash bench/bench_resample.sh [FRAMES]   (default 100000)
set -euo pipefail
cd "$(dirname "$0")/.."
frames="${1:-100000}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j 2 --target bench_resample rotinterp >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
./build/bench/bench_resample --frames "$frames" --keep "$work/long.bvh"
for args in "" "--fps 30"; do
  start=$(date +%s%N)
  ./build/rotinterp resample "$work/long.bvh" -o "$work/out.bvh" $args
  end=$(date +%s%N)
  echo "cli: rotinterp resample ${args:-(same rate)}: $(( (end - start) / 1000000 )) ms wall"
done
