#!/usr/bin/env bash
# The README's main job: installs what is missing, builds, renders the bundled default dataset.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

output="${UV_OUTPUT:-$UV_ROOT/out}"
say "Rendering the default dataset into $output"
PYTHONPATH="$UV_PYTHONPATH" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  /usr/bin/python3 "$UV_ROOT/Testing/Python/render_default.py" --output "$output"
