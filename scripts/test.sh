#!/usr/bin/env bash
# Command (2): install what is missing, build, run the whole test suite — once in a
# Release build, then again in an AddressSanitizer + UndefinedBehaviorSanitizer build.
# ROTINTERP_SKIP_SANITIZERS=1 runs only the first pass (for quick local runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)

echo "== Release build and tests"
# The Python module is built for Debian's python3, whose numpy, scipy and pytest the
# install script brings (a python3 earlier on PATH, e.g. pyenv's, may have none).
python=()
[ -x /usr/bin/python3 ] && python=(-DPython_EXECUTABLE=/usr/bin/python3)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS="-Werror" "${python[@]}"
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"

if [ "${ROTINTERP_SKIP_SANITIZERS:-0}" != 1 ]; then
  echo "== ASan + UBSan build and tests"
  # Only what runs a test under the sanitizers: no benchmarks, no header-alone units
  # (the Release pass checked those), no Python module (python is not sanitized).
  # -O1 -g1 in the build type's own flags: they come after CMAKE_CXX_FLAGS, so an -O1
  # there lost to RelWithDebInfo's -O2 -g. -g1 keeps file:line in the sanitizers' stack
  # traces at about half the compile time of -O2 -g (docs/development.md).
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROTINTERP_SANITIZE=ON \
    -DROTINTERP_BUILD_BENCH=OFF -DROTINTERP_HEADER_CHECKS=OFF -DCMAKE_CXX_FLAGS="-Werror" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
  cmake --build build-asan -j "$jobs"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  export LSAN_OPTIONS="suppressions=$PWD/.ci/lsan.supp:print_suppressions=0"
  ctest --test-dir build-asan --output-on-failure -j "$jobs"
fi
