#!/usr/bin/env bash
# The README's test command: installs what is missing, builds both builds, runs every test under Xvfb
# (GoogleTest, Python, pvbatch/pvpython plugin tests). Exits non-zero on any failure.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

say "Running the tests of $UV_BUILD/vtk and $UV_BUILD/paraview under Xvfb"
test_dirs=("$UV_BUILD/vtk")
[ -d "$UV_BUILD/paraview" ] && test_dirs+=("$UV_BUILD/paraview")
status=0
# UV_TEST_LABEL (platforms.sh sets `platform`) runs only the tests of that ctest label.
label_args=()
[ -z "${UV_TEST_LABEL:-}" ] || label_args=(-L "$UV_TEST_LABEL")
# Xvfb runs with -noreset: by default it resets whenever its last client disconnects, and a client
# connecting then is refused: "bad X server connection" (an abort in vtkXOpenGLRenderWindow) or,
# when it hits ParaView's display check, "remote rendering ... not available" and a 2-rank pvbatch
# that hangs in ordered compositing; with both cores busy, two-rank runs failed that way often.
# No test is rerun: a flaky test is a bug to find.
for dir in "${test_dirs[@]}"; do
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
    ctest --test-dir "$dir" "${label_args[@]}" --output-on-failure -j "$(nproc)" --timeout 900 || status=1
done
exit "$status"
