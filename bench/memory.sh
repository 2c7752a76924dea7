#!/usr/bin/env bash
# Peak memory (max RSS, GNU time) of `rotinterp resample` and `rotinterp eval` on
# generated clips of growing length, to show it grows in proportion to the clip.
# Usage: bash bench/memory.sh [FRAMES...]   (default: 100000 300000 1000000)
# Env: JOINTS (default 12, `synth --kind smooth`), FPS (default 100),
#      EVAL_METHODS (default slerp,squad), BUILD (default build).
# Needs /usr/bin/time (Debian package `time`) and about 0.4 GB of disk per
# million frames at 12 joints (in $TMPDIR).
set -euo pipefail
cd "$(dirname "$0")/.."
joints="${JOINTS:-12}"
fps="${FPS:-100}"
methods="${EVAL_METHODS:-slerp,squad}"
build="${BUILD:-build}"
[ "$#" -gt 0 ] || set -- 100000 300000 1000000
[ -x /usr/bin/time ] || { echo "memory.sh: needs /usr/bin/time (apt-get install time)" >&2; exit 1; }
if [ ! -x "$build/rotinterp" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j 2 --target rotinterp >/dev/null
fi
cli="$build/rotinterp"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Runs a command under GNU time; prints "<max RSS MiB> <wall s>".
measure() {
  /usr/bin/time -f '%M %e' -o "$work/time" "$@" >/dev/null 2>"$work/stderr" || {
    cat "$work/stderr" >&2
    exit 1
  }
  awk '{ printf "%.0f %.1f\n", $1 / 1024, $2 }' "$work/time"
}

printf '%-9s %-7s %-9s %-9s | %-24s | %-24s\n' frames joints keys BVH_MiB "resample: MiB, s, B/key" \
  "eval: MiB, s, B/key"
for frames in "$@"; do
  clip="$work/clip.bvh"
  seconds=$(awk -v n="$frames" -v f="$fps" 'BEGIN { printf "%.6f", (n - 1) / f }')
  "$cli" synth "$clip" --kind smooth --joints "$joints" --seconds "$seconds" --fps "$fps" --seed 7 -q
  keys=$((frames * joints))
  size=$(stat -c %s "$clip")
  read -r r_mib r_s < <(measure "$cli" resample "$clip" -o "$work/out.bvh" -q)
  rm -f "$work/out.bvh"
  read -r e_mib e_s < <(measure "$cli" eval "$clip" --methods "$methods" --keep-every 4 -j 2 --no-plots -q \
    -o "$work/eval")
  rm -rf "$work/eval"
  printf '%-9s %-7s %-9s %-9s | %6s %7s %8s | %6s %7s %8s\n' "$frames" "$joints" "$keys" $((size / 1048576)) \
    "$r_mib" "$r_s" $((r_mib * 1048576 / keys)) "$e_mib" "$e_s" $((e_mib * 1048576 / keys))
  rm -f "$clip" "$clip.synth"
done
