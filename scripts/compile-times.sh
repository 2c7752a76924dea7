#!/usr/bin/env bash
# Compiler and linker launcher that logs each step's CPU and wall seconds, to find what
# dominates a build's time (docs/development.md, "Build time"):
#   cmake -S . -B build-times -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/compile-times.sh \
#         -DCMAKE_CXX_LINKER_LAUNCHER=$PWD/scripts/compile-times.sh ...
#   ROTINTERP_COMPILE_LOG=$PWD/times.log cmake --build build-times -j2
#   bash scripts/compile-times.sh --report times.log
# Each log line: user-s sys-s wall-s output. CPU seconds (user + sys) are the figure to
# compare on a shared machine; wall seconds grow with whatever else runs.
set -euo pipefail
if [ "${1:-}" = --report ]; then
  log=$2
  echo "# top objects and links (CPU-s = user + sys)"
  awk '{printf "%8.1f %8.1f  %s\n", $1 + $2, $3, $4}' "$log" | sort -rn | head -"${3:-25}"
  echo "# per target (CPU-s, objects)"
  awk '{t = $4; sub(/.*CMakeFiles\//, "", t); sub(/\.dir\/.*/, "", t); cpu[t] += $1 + $2; n[t]++}
       END {for (t in cpu) printf "%8.1f %4d  %s\n", cpu[t], n[t], t}' "$log" | sort -rn
  awk '{c += $1 + $2} END {printf "# total: %.1f CPU-s in %d steps\n", c, NR}' "$log"
  exit 0
fi
log=${ROTINTERP_COMPILE_LOG:?set ROTINTERP_COMPILE_LOG to the log file}
out=unknown
args=("$@")
for ((i = 0; i < ${#args[@]} - 1; i++)); do
  [ "${args[i]}" = -o ] && out=${args[i + 1]}
done
exec /usr/bin/time -a -o "$log" -f "%U %S %e $out" "$@"
