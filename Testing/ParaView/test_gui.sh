#!/usr/bin/env bash
# Starts the real ParaView GUI under Xvfb with the plugin, lets gui_script.py select the new
# representation, waits until it has rendered, screenshots the whole screen and checks the GUI
# listed the new entries. Usage: test_gui.sh <plugin.so, or the name of an installed plugin> <output dir>
# <paraview python path, or "" for none> [paraview executable (default: paraview)]
set -uo pipefail
plugin="$1"; output="$2"; pythonpath="$3"; executable="${4:-paraview}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mkdir -p "$output"
rm -f "$output/gui_entries.txt" "$output/paraview_gui.png"
export UV_PLUGIN="$plugin" UV_GUI_OUTPUT="$output" UV_PARAVIEW="$executable"
# Runs inside xvfb-run: DISPLAY is the virtual screen.
inner='
  if [ -n "$0" ]; then export PYTHONPATH="$0"; else unset PYTHONPATH; fi
  "$UV_PARAVIEW" --script="$1/gui_script.py" > "$UV_GUI_OUTPUT/paraview_gui.log" 2>&1 &
  gui=$!
  for i in $(seq 1 120); do
    [ -s "$UV_GUI_OUTPUT/gui_entries.txt" ] && break
    kill -0 $gui 2>/dev/null || break
    sleep 1
  done
  sleep 3  # let the GUI repaint its panels after the render
  xwd -root -silent | convert xwd:- "$UV_GUI_OUTPUT/paraview_gui.png"
  kill $gui 2>/dev/null; wait $gui 2>/dev/null
  true'
xvfb-run -a -s "-screen 0 1280x800x24 -noreset" bash -c "$inner" "$pythonpath" "$here"
if [ ! -s "$output/gui_entries.txt" ]; then
  echo "the GUI did not get as far as rendering; its log:"; tail -20 "$output/paraview_gui.log"; exit 1
fi
cat "$output/gui_entries.txt"
grep -q "representation: Volume (Pre-integrated Tetrahedra)" "$output/gui_entries.txt" || exit 1
grep -q "representation: Volume (Hexahedral Ray Cast)" "$output/gui_entries.txt" || exit 1
grep -q "representation: Volume (Barycentric Shells)" "$output/gui_entries.txt" || exit 1
grep -q "filter: HexahedraToTetrahedra in Unstructured Volume" "$output/gui_entries.txt" || exit 1
[ -s "$output/paraview_gui.png" ] || { echo "no screenshot"; exit 1; }
echo "paraview GUI OK: screenshot $output/paraview_gui.png"
