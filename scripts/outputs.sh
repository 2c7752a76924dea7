#!/usr/bin/env bash
# Writes what rotinterp makes of every clip in ../shared/data, so that two builds
# can be compared byte for byte (a refactoring must not change a single output):
#   resample: every method, every clip, keys at every 4th frame, as BVH; and at 30 Hz;
#   eval:     errors.csv and summary.json over the whole folder (subframes too);
#   render:   the default frames of every clip, all methods, with a trail, as PNG;
#   reduce:   every clip and the sample walk, every method, the kept keys as JSON; slerp's
#             as GLB and FBX too (the default budget).
# Usage: bash scripts/outputs.sh BUILD_DIR OUT_DIR
#        bash scripts/outputs.sh --compare OLD_BUILD_DIR NEW_BUILD_DIR
# --compare writes both sets under build-outputs/ and diffs them: exit 0 only if
# every file is identical.
set -euo pipefail
cd "$(dirname "$0")/.."
data=../shared/data

if [ "${1:-}" = --compare ]; then
  [ $# -eq 3 ] || { echo "usage: $0 --compare OLD_BUILD_DIR NEW_BUILD_DIR" >&2; exit 2; }
  rm -rf build-outputs && mkdir -p build-outputs
  bash "$0" "$2" build-outputs/old
  bash "$0" "$3" build-outputs/new
  files=$(find build-outputs/old -type f | wc -l)
  if diff -r build-outputs/old build-outputs/new >build-outputs/diff.txt; then
    echo "identical: $files files (build-outputs/old vs build-outputs/new)"
  else
    echo "DIFFERENT: see build-outputs/diff.txt" >&2
    diff -rq build-outputs/old build-outputs/new >&2 || true
    # How far apart the numbers of errors.csv are, when they are.
    python3 - build-outputs/old/eval/errors.csv build-outputs/new/eval/errors.csv >&2 <<'PY' || true
import csv, sys
a, b = (list(csv.reader(open(p))) for p in sys.argv[1:3])
if a == b or len(a) != len(b): sys.exit()
for i, col in enumerate(a[0]):
    rel = 0.0
    for x, y in zip(a[1:], b[1:]):
        try: fx, fy = float(x[i]), float(y[i])
        except ValueError: continue
        if max(abs(fx), abs(fy)) > 1e-3: rel = max(rel, abs(fx - fy) / max(abs(fx), abs(fy)))
    if rel: print(f"errors.csv {col}: largest relative difference {rel:.3g} (values above 1e-3)")
PY
    exit 1
  fi
  exit 0
fi

[ $# -eq 2 ] || { echo "usage: $0 BUILD_DIR OUT_DIR" >&2; exit 2; }
bin=$(realpath "$1")/rotinterp
out=$2
[ -x "$bin" ] || { echo "$0: no rotinterp in $1" >&2; exit 2; }
mkdir -p "$out/resample" "$out/render" "$out/reduce"
clips=$(find "$data" -type f \( -name '*.bvh' -o -name '*.fbx' \) | sort)
methods=$("$bin" methods | awk 'NR > 1 { print $1 }')

# A clip the reader refuses is an output too: its message (and exit status) must not change.
for clip in $clips; do
  name=$(basename "$clip")
  for m in $methods; do
    status=0
    "$bin" resample "$clip" -o "$out/resample/$name.$m.bvh" --keep-every 4 --method "$m" -q \
      2>"$out/resample/$name.$m.err" || status=$?
    echo "$status" >>"$out/resample/$name.$m.err"
  done
  # A new rate on every clip (sparse-key FBX files have no rate of their own to keep every 4th frame of).
  status=0
  "$bin" resample "$clip" -o "$out/resample/$name.fps30.bvh" --fps 30 -q 2>"$out/resample/$name.fps30.err" || status=$?
  echo "$status" >>"$out/resample/$name.fps30.err"
  # The trail of the third joint (a joint with a parent and, usually, a child).
  joint=$("$bin" info "$clip" --json 2>/dev/null |
    python3 -c 'import json, sys; j = json.load(sys.stdin)["joints"]; print(j[min(2, len(j) - 1)]["name"])' 2>/dev/null || true)
  status=0
  "$bin" render "$clip" -o "$out/render/$name" --size 320x180 ${joint:+--trail "$joint"} -q \
    >"$out/render/$name.out" 2>"$out/render/$name.err" || status=$?
  echo "$status" >>"$out/render/$name.err"
done
# reduce: the selection's keys (and, for slerp, the written GLB and FBX files).
for clip in $clips samples/walk.bvh; do
  name=$(basename "$clip")
  for m in $methods; do
    [ "$m" = source ] && continue  # the file's own curves: nothing to select keys for
    status=0
    "$bin" reduce "$clip" -o "$out/reduce/$name.$m.json" -m "$m" -q 2>"$out/reduce/$name.$m.err" || status=$?
    echo "$status" >>"$out/reduce/$name.$m.err"
  done
  for ext in glb fbx; do
    status=0
    "$bin" reduce "$clip" -o "$out/reduce/$name.slerp.$ext" -q 2>"$out/reduce/$name.$ext.err" || status=$?
    echo "$status" >>"$out/reduce/$name.$ext.err"
  done
done
status=0
"$bin" eval "$data" -o "$out/eval" --subframe 2 --no-plots -q -j 2 2>"$out/eval.err" || status=$?
echo "$status" >>"$out/eval.err"
# What may differ between two runs: the output paths in messages, the clock.
find "$out" -name '*.err' -o -name '*.out' | xargs sed -i "s|$out/|OUT/|g"
sed -i -E '/"(seconds|started)":/d' "$out/eval/summary.json"
echo "$out: $(find "$out" -type f | wc -l) files"
