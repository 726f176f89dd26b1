#!/usr/bin/env bash
# Builds the VTK module, its Python wrapping and the C++ tests with AddressSanitizer and
# UndefinedBehaviorSanitizer (UV_SANITIZE=ON) into build/sanitize, runs the tests labelled `sanitize`
# under Xvfb and exits non-zero on any failure or any sanitizer report (leaks included).
# Expects the packages of setup.sh to be installed; does not touch build/vtk or build/paraview.
set -euo pipefail

UV_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
UV_BUILD="${UV_BUILD:-$UV_ROOT/build}"
build="$UV_BUILD/sanitize"
jobs="${UV_JOBS:-$(nproc)}"
say() { printf '\n== %s\n' "$*"; }

say "Configuring and building $build (UV_SANITIZE=ON)"
mkdir -p "$build"
cmake -S "$UV_ROOT" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DUV_BUILD_PARAVIEW_PLUGIN=OFF -DUV_SANITIZE=ON \
  >"$UV_BUILD/sanitize-configure.log" 2>&1 || { cat "$UV_BUILD/sanitize-configure.log"; exit 1; }
cmake --build "$build" -j "$jobs"

# Every report also goes to a file of its own, so that one from a process whose exit status is lost
# still fails the run. The Python tests add their leak suppressions (Testing/Scripts/lsan.supp).
reports="$build/Testing/sanitizer-reports"
rm -rf "$reports"
mkdir -p "$reports"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:log_path=$reports/asan"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:log_path=$reports/ubsan"

say "Running the tests labelled sanitize in $build under Xvfb"
status=0
# No test is rerun: a flaky test is a bug to find.
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  ctest --test-dir "$build" -L sanitize --output-on-failure -j "$jobs" --timeout 1800 || status=1

if [ -n "$(ls -A "$reports")" ]; then
  say "Sanitizer reports in $reports"
  for report in "$reports"/*; do
    printf -- '--- %s\n' "$report"
    cat "$report"
  done
  status=1
fi
[ "$status" -eq 0 ] && say "Sanitized run clean" || say "Sanitized run FAILED"
exit "$status"
