#!/usr/bin/env bash
# Writes what every io path of rotinterp makes of a set of shared clips, so that a
# refactoring of io (issue 46) can be checked byte for byte: `diff -r BEFORE AFTER`.
# Faster than scripts/outputs.sh (no render, few methods), and wider on io: every
# writable format (bvh, fbx, fbx ASCII, glb, gltf, dae, a folder run's CSV manifest),
# reduce to json/glb/fbx, info as text, JSON and curves, eval's tables, the
# file's own motion (-m source) and several takes (--anim all).
# Usage: bash scripts/io-outputs.sh BUILD_DIR OUT_DIR
# Give the two runs OUT_DIRs whose paths are equally long (/work/x-before,
# /work/x-after2): info --summary sizes its columns to the paths it prints.
# Nothing here varies between runs but the output paths in messages (rewritten to
# OUT/) and the clock (rewritten to T, or removed; see the end). The FBX writer
# embeds a fixed creation time and FileId (src/io/fbx/fbx_write.cpp), so FBX files
# compare as they are; assimp's Collada exporter writes the time of day.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -eq 2 ] || { echo "usage: $0 BUILD_DIR OUT_DIR" >&2; exit 2; }
bin=$(realpath "$1")/rotinterp
out=$(realpath -m "$2")
[ -x "$bin" ] || { echo "$0: no rotinterp in $1" >&2; exit 2; }
data=../shared/data
rm -rf "$out" && mkdir -p "$out"/{resample,reduce,info,eval,takes,folder}
clips="samples/walk.bvh $data/bvh/bvhio_example.bvh $data/bvh/NC_bandai2_raise-up-both-hands_active_031.bvh
  $data/fbx/assimp_huesitos.fbx $data/fbx/digitalrune_Dude.fbx $data/fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx
  $data/fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx $data/fbx/ufbx_maya_anim_layers_over_acc_orders_7500_ascii.fbx
  $data/fbx/ufbx_maya_game_sausage_6100_binary_wiggle.fbx $data/curves/ufbx_maya_auto_clamp_7100_binary.fbx"

# run NAME CMD...: stdout to NAME.out, stderr and the exit status to NAME.err.
run() {
  local name=$1 status=0
  shift
  "$@" >"$name.out" 2>"$name.err" || status=$?
  echo "exit $status" >>"$name.err"
}

for clip in $clips; do
  n=$(basename "$clip")
  for ext in bvh fbx glb gltf dae; do
    run "$out/resample/$n.k4.$ext" "$bin" resample "$clip" -o "$out/resample/$n.k4.$ext" --keep-every 4 -m c2
  done
  run "$out/resample/$n.ascii" "$bin" resample "$clip" -o "$out/resample/$n.ascii.fbx" --fbx-ascii --fps 24
  run "$out/resample/$n.cm" "$bin" resample "$clip" -o "$out/resample/$n.cm.bvh" --fps 30 --out-unit cm
  for ext in bvh fbx glb; do
    run "$out/resample/$n.source.$ext" "$bin" resample "$clip" -o "$out/resample/$n.source.$ext" -m source
  done
  # A written glTF and FBX read back: the reader of each format on our own output.
  for ext in glb fbx; do
    run "$out/resample/$n.back.$ext" "$bin" resample "$out/resample/$n.k4.$ext" -o "$out/resample/$n.back.$ext.bvh"
  done
  for ext in json glb fbx; do
    run "$out/reduce/$n.$ext" "$bin" reduce "$clip" -o "$out/reduce/$n.$ext" --tolerance 1deg,2mm
  done
  run "$out/info/$n.text" "$bin" info "$clip"
  run "$out/info/$n.json" "$bin" info "$clip" --json
  run "$out/info/$n.curves" "$bin" info "$clip" --curves --sample 24
  run "$out/takes/$n" "$bin" resample "$clip" --anim all -o "$out/takes/$n.{anim}.bvh" -m slerp
  run "$out/takes/$n.all" "$bin" resample "$clip" --anim all -o "$out/takes/$n.all.glb" -m slerp
done
run "$out/info/summary" "$bin" info $clips "$out/resample" --summary -j 1
run "$out/eval/run" "$bin" eval $clips -o "$out/eval/dir" -m slerp,clamped,c2 --keep-every 2,8 --no-plots -j 1 --table md
run "$out/eval/source" "$bin" eval $data/fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx samples/walk.bvh \
  -o "$out/eval/source-dir" --truth source -m slerp --no-plots -j 1
run "$out/folder/bvh" "$bin" resample "$data/bvh" -o "$out/folder/bvh-out" --fps 30 --format fbx -j 1 \
  --manifest "$out/folder/manifest.csv"
run "$out/folder/reduce" "$bin" reduce "$data/fbx" -o "$out/folder/reduce-out" -j 1

# What may differ between two runs: the output paths in messages and files, the clock
# (durations in messages, assimp's Collada <created>/<modified>, eval's and the manifest's).
grep -rlF "$out/" "$out" | xargs -r sed -i "s|$out/|OUT/|g"
find "$out" -name '*.out' -exec sed -i -E 's/[0-9]+(\.[0-9]+)? s([,;) ]|$)/T s\2/g; s/\([0-9.]+ MB\/s\)/(R MB\/s)/g' {} +
find "$out" -name '*.dae' -exec sed -i -E 's#<(created|modified)>[^<]*<#<\1>T<#' {} +
find "$out" -name summary.json -exec sed -i -E '/"(seconds|started)":/d' {} +
[ -f "$out/folder/manifest.csv" ] && python3 - "$out/folder/manifest.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
drop = {rows[0].index("seconds")}
csv.writer(open(sys.argv[1], "w", newline="")).writerows([[c for i, c in enumerate(r) if i not in drop] for r in rows])
PY
echo "$out: $(find "$out" -type f | wc -l) files"
