#!/usr/bin/env bash
# Compiles every public header alone (a translation unit holding only its
# #include), so that each includes what it uses. Exit 1 naming the headers that don't.
# Usage: bash scripts/headers.sh
set -uo pipefail
cd "$(dirname "$0")/.."
flags=(-std=c++17 -fsyntax-only -Wall -Wextra -Werror -Iinclude -Irender/include -I/usr/include/eigen3)
failed=0
for h in $(find include render/include -name '*.h' | sort); do
  rel=${h#include/}
  rel=${rel#render/include/}
  if ! echo "#include \"$rel\"" | ${CXX:-c++} "${flags[@]}" -x c++ - 2>/tmp/headers.$$.log; then
    echo "$h does not compile alone:" >&2
    head -n 5 /tmp/headers.$$.log >&2
    failed=1
  fi
done
rm -f /tmp/headers.$$.log
[ $failed = 0 ] && echo "every header compiles alone ($(find include render/include -name '*.h' | wc -l) headers)"
exit $failed
