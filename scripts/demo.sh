#!/usr/bin/env bash
# Command (1): install what is missing, build in Release, run the main job on the
# bundled sample and print the paths of what it wrote.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target rotinterp
out=out/demo
mkdir -p "$out"
./build/rotinterp methods | tee "$out/methods.txt"
echo "wrote: $out/methods.txt"
# The bundled sample (samples/README.md): change its rate, and rebuild it from every 4th frame.
./build/rotinterp resample samples/walk.bvh -o "$out/walk_50hz.bvh" --fps 50
echo "wrote: $out/walk_50hz.bvh"
./build/rotinterp resample samples/walk.bvh -o "$out/walk_keep4.bvh" --keep-every 4
echo "wrote: $out/walk_keep4.bvh"
