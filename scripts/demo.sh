#!/usr/bin/env bash
# Command (1): install what is missing, build in Release (the CLI and the Python module), run the main job on the
# bundled sample (resample + eval + render) and print the paths of what it wrote.
# Usage: scripts/demo.sh [OUT_DIR] (default out/demo). With $ROTINTERP set (the test suite's
# demo_script), that binary runs the job and nothing is installed or built.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${ROTINTERP:-}" ]; then
  bash scripts/install-deps.sh
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  # The CLI, and the Python module (rotinterp_python) that the README's and docs/' python blocks
  # import with PYTHONPATH=build/python.
  cmake --build build -j "$(nproc)" --target rotinterp rotinterp_python
fi
out=${1:-out/demo}
rm -rf "$out"
mkdir -p "$out"
rotinterp=${ROTINTERP:-./build/rotinterp}
sample=samples/walk.bvh   # made by `rotinterp synth` (samples/README.md)

# Resample: a new frame rate, and the clip rebuilt from every 4th frame.
$rotinterp resample "$sample" -o "$out/walk_50hz.bvh" --fps 50 --quiet
$rotinterp resample "$sample" -o "$out/walk_keep4.bvh" --keep-every 4 --quiet
# Eval: every method at key spacings 2, 4, 8, 16 — table on stdout, CSV/JSON/plots in a directory.
$rotinterp eval "$sample" -o "$out/eval" --quiet
# Render: three methods side by side for a few frames between keys, a trail (one method's curve
# per panel, so side by side) and a contact sheet.
$rotinterp render "$sample" -o "$out/render" --methods slerp,squad,clamped --keep-every 8 --frames 20:60:10 \
  --view side --trail LeftHand --sheet --quiet

echo "wrote:"
find "$out" -type f | sort | sed 's/^/  /'
