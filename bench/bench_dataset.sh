#!/usr/bin/env bash
# Dataset throughput: `rotinterp resample DIR -o OUT --fps 30 -j 2` against assimp
# importing the same files with 2 processes (`assimp info`, as a user would run it
# over a folder), in MB of input per second, in the same run. Two folders: the BVH
# clips of ../shared/data, and a generated folder of MB megabytes of synthetic
# 120 Hz walks (default 1024).
# Usage: bash bench/bench_dataset.sh [MB]
set -euo pipefail
cd "$(dirname "$0")/.."
megabytes="${1:-1024}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j 2 --target rotinterp >/dev/null
command -v assimp >/dev/null || { echo "bench_dataset: needs the assimp command (package assimp-utils)" >&2; exit 1; }
bin="$PWD/build/rotinterp"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Generated folder: 90 s walks at 120 Hz (about 9.7 MB each) until MB is reached.
mkdir -p "$work/generated"
seed=1
while [ "$(du -sm "$work/generated" | cut -f1)" -lt "$megabytes" ]; do
  "$bin" synth "$work/generated/walk$seed.bvh" --kind walk --seconds 90 --fps 120 --seed "$seed" -q
  rm -f "$work/generated/walk$seed.bvh.synth"
  seed=$((seed + 1))
done
mkdir -p "$work/shared"
# The shared clips by their relative path (never copied into the project: linked here, in the temp dir).
for f in ../shared/data/bvh/*.bvh; do ln -s "$PWD/$f" "$work/shared/"; done

TIMEFORMAT='%R %U %S'
measure() {  # prints "wall cpu" of the command, children included
  local t
  t=$( { time "$@" >/dev/null 2>&1; } 2>&1 )
  awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' <<<"$t"
}
for set in shared generated; do
  dir="$work/$set"
  mb=$(find -L "$dir" -name '*.bvh' -printf '%s\n' | awk '{ s += $1 } END { printf "%.1f", s / 1e6 }')
  files=$(find -L "$dir" -name '*.bvh' | wc -l)
  # Warm the page cache for both, so both read from memory.
  cat "$dir"/*.bvh >/dev/null
  read -r a_wall a_cpu < <(measure bash -c "find -L '$dir' -name '*.bvh' -print0 | xargs -0 -n 1 -P 2 assimp info")
  rm -rf "$work/out"
  read -r r_wall r_cpu < <(measure "$bin" resample "$dir" -o "$work/out" --fps 30 -j 2 -q)
  awk -v set="$set" -v files="$files" -v mb="$mb" -v aw="$a_wall" -v ac="$a_cpu" -v rw="$r_wall" -v rc="$r_cpu" 'BEGIN {
    printf "%s: %d files, %.1f MB\n", set, files, mb
    printf "  assimp info, 2 processes:      %6.2f s wall %6.2f s CPU  %7.1f MB/s\n", aw, ac, mb / aw
    printf "  rotinterp resample --fps 30 -j 2: %6.2f s wall %6.2f s CPU  %7.1f MB/s  (%.2fx assimp wall, %.2fx CPU)\n", rw, rc, mb / rw, rw / aw, rc / ac
  }'
done
