#!/usr/bin/env bash
# docs/gallery/'s pictures of real captures no one here made (../shared/data): the Bandai Namco walk
# (its root a ground marker the walker leaves behind) and a CMU clip at 120 Hz, each in the overlay
# and side by side. Usage: scripts/gallery.sh [OUT_DIR] — default docs/gallery; the rotinterp run is
# $ROTINTERP (default build/rotinterp), the clips under $ROTINTERP_SHARED_DATA (default ../shared/data).
set -euo pipefail
out=${1:-docs/gallery}
ri=${ROTINTERP:-build/rotinterp}
data=${ROTINTERP_SHARED_DATA:-../shared/data}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# name clip keys frame [options]: frame FRAME of CLIP rebuilt from every KEYS-th frame, as OUT/NAME.png.
shot() {
  local name=$1 clip=$2 keys=$3 frame=$4
  shift 4
  "$ri" render "$data/$clip" -o "$work/$name" -m slerp,squad,c2 --keep-every "$keys" --frames "$frame" \
    --size 720x405 -q "$@" >/dev/null
  cp "$work/$name/frame_$(printf %06d "$frame").png" "$out/$name.png"
}
shot bandai_walk_overlay bvh/NC_bandai1_walk_normal_001.bvh 8 100
shot bandai_walk_side bvh/NC_bandai1_walk_normal_001.bvh 8 100 --view side
shot cmu_walk_overlay bvh/cmu_01_01.bvh 24 1212
shot cmu_walk_side bvh/cmu_01_01.bvh 24 1212 --view side
