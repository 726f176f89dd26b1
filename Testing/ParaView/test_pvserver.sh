#!/usr/bin/env bash
# pvserver on 2 MPI ranks, a pvpython client: the client selects the representation, the server
# renders (ordered compositing), the client saves the image and compares it with the baseline.
# Usage: test_pvserver.sh <mpiexec> "<mpiexec flags>" <pvpython> <plugin.so> <preintegrated|hexahedral|barycentric>
#          <output.png> <baseline.png>
set -uo pipefail
mpiexec="$1"; flags="$2"; pvpython="$3"; plugin="$4"; mapper="$5"; output="$6"; baseline="$7"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
port=$((20000 + RANDOM % 20000))
log="${output%.png}_pvserver.log"
# shellcheck disable=SC2086
"$mpiexec" $flags -np 2 pvserver --server-port="$port" --force-offscreen-rendering > "$log" 2>&1 &
server=$!
for i in $(seq 1 60); do grep -q "Accepting connection" "$log" && break; sleep 0.5; done
env -u PYTHONPATH UV_SERVER="localhost:$port" "$pvpython" --force-offscreen-rendering \
  "$here/test_plugin_representation.py" "$plugin" "$mapper" "$output" "$baseline" 10 0.03
status=$?
kill $server 2>/dev/null; wait $server 2>/dev/null
exit $status
