#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for
# SECONDS (default 60) seconds: fuzz_read_bvh, fuzz_read_any, fuzz_read_fbx, fuzz_read_gltf, fuzz_interp.
# Usage: bash scripts/fuzz.sh [SECONDS] [TARGET...]
# Seeds: ../shared/data plus tests/fuzz/corpus/<kind>; new inputs go to
# build-fuzz/corpus/<target>; crashes to build-fuzz/artifacts/<target>/; the whole
# log (a crash's stack) to build-fuzz/<target>.log.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_read_bvh fuzz_read_any fuzz_read_fbx fuzz_read_gltf fuzz_interp)

bash scripts/install-deps.sh
command -v clang++ >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -q clang libclang-rt-14-dev
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROTINTERP_FUZZ=ON \
  -DROTINTERP_BUILD_TESTS=OFF -DROTINTERP_BUILD_BENCH=OFF -DROTINTERP_BUILD_RENDER=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
data=../shared/data
for t in "${targets[@]}"; do
  case $t in
    fuzz_read_bvh) seeds=("$data/bvh" tests/fuzz/corpus/bvh) ;;
    fuzz_read_any)
      # Seeds: the real clips with the first byte choosing their importer (kept in build-fuzz, not the project).
      mkdir -p build-fuzz/seeds/any
      for f in "$data"/bvh/*.bvh; do { printf '\x00'; head -c 200000 "$f"; } > "build-fuzz/seeds/any/$(basename "$f")"; done
      for f in "$data"/fbx/*.fbx; do { printf '\x01'; cat "$f"; } > "build-fuzz/seeds/any/$(basename "$f")"; done
      seeds=(build-fuzz/seeds/any) ;;
    fuzz_read_fbx) seeds=("$data/fbx" "$data/curves") ;;
    fuzz_read_gltf)
      # Seeds: GLB files rotinterp writes from the shared BVH clips (kept in build-fuzz).
      mkdir -p build-fuzz/seeds/gltf
      [ -x build/rotinterp ] && for f in "$data"/bvh/*.bvh; do
        build/rotinterp resample "$f" -o "build-fuzz/seeds/gltf/$(basename "$f" .bvh).glb" --range 0:0.5 -q || true
      done
      seeds=(build-fuzz/seeds/gltf) ;;
    fuzz_interp) seeds=(tests/fuzz/corpus/interp) ;;
  esac
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/artifacts/$t"
  echo "== $t for ${seconds}s"
  ./build-fuzz/tests/fuzz/"$t" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 -max_len=262144 \
    -artifact_prefix="build-fuzz/artifacts/$t/" -print_final_stats=1 \
    "build-fuzz/corpus/$t" "${seeds[@]}" 2>&1 | tee "build-fuzz/$t.log" | tail -n 12
done
