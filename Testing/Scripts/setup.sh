#!/usr/bin/env bash
# Installs what the project needs on Debian 12 and builds it twice: build/vtk (system VTK 9.1 +
# Python) and build/paraview (the ParaView 5.11 plugin). Idempotent: re-running only rebuilds.
# Sourced by main.sh and test.sh; exports UV_* variables describing the builds.
set -euo pipefail

UV_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
UV_BUILD="${UV_BUILD:-$UV_ROOT/build}"
# ParaView's Python lives here (see below); pvbatch/pvpython need it on PYTHONPATH.
UV_PARAVIEW_PYTHON_PREFIX=/opt/unstructuredvolume/paraview-python
UV_PARAVIEW_PYTHONPATH="$UV_PARAVIEW_PYTHON_PREFIX/usr/lib/python3/dist-packages"
export UV_ROOT UV_BUILD UV_PARAVIEW_PYTHONPATH

say() { printf '\n== %s\n' "$*"; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

packages=(
  cmake ninja-build g++ pkg-config
  libvtk9-dev python3-vtk9 python3-dev
  paraview paraview-dev mpi-default-bin
  qtbase5-dev qttools5-dev qtxmlpatterns5-dev-tools libqt5opengl5-dev libqt5svg5-dev
  libglm-dev googletest libgtest-dev
  xvfb xauth
  x11-apps imagemagick  # xwd and convert: the ParaView GUI test's screenshot
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' || missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  say "Installing ${missing[*]}"
  as_root apt-get update -q
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  say "Debian packages already installed"
fi

# Debian's python3-paraview conflicts with python3-vtk9 (both ship vtkmodules/), yet pvbatch needs
# the former and libvtk9-dev the latter. So python3-paraview is unpacked privately, and pvbatch and
# pvpython get it through PYTHONPATH. ParaView's CMake package also checks that the files of its
# imported targets exist: those that python3-paraview would have installed (its Python modules, with
# untagged *.so names distinct from python3-vtk9's cpython-tagged ones, and bin/pvpython) are linked
# into place from the private copy, so /usr/bin/python3 still imports Debian's VTK.
if [ ! -f "$UV_PARAVIEW_PYTHONPATH/paraview/simple.py" ]; then
  say "Unpacking python3-paraview into $UV_PARAVIEW_PYTHON_PREFIX"
  download_dir="$(mktemp -d)"
  chmod 755 "$download_dir"
  (cd "$download_dir" && apt-get download python3-paraview)
  as_root mkdir -p "$UV_PARAVIEW_PYTHON_PREFIX"
  as_root dpkg -x "$download_dir"/python3-paraview_*.deb "$UV_PARAVIEW_PYTHON_PREFIX"
  rm -rf "$download_dir"
fi
paraview_cmake=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11
link_missing() { # relative paths under /usr, on standard input
  while read -r relative; do
    target="/usr/$relative"
    source="$UV_PARAVIEW_PYTHON_PREFIX/usr/$relative"
    if [ ! -e "$target" ] && [ -e "$source" ]; then
      as_root mkdir -p "$(dirname "$target")"
      as_root ln -sf "$source" "$target"
      linked=$((linked + 1))
    fi
  done
}
linked=0
# Files ParaView's imported targets name, and its wrapping hierarchy files (not Python packages).
link_missing < <(grep -ho '"${_IMPORT_PREFIX}/[^"]*"' "$paraview_cmake"/*-targets-*.cmake "$paraview_cmake"/vtk/*-targets-*.cmake |
                 sed 's/"${_IMPORT_PREFIX}\///; s/"$//' | sort -u)
link_missing < <(cd "$UV_PARAVIEW_PYTHON_PREFIX/usr" && find . -type f -not -path './lib/python3/*' | sed 's|^\./||')
[ "$linked" -eq 0 ] || say "Linked $linked files of python3-paraview for ParaView's CMake package"

mkdir -p "$UV_BUILD"
jobs="$(nproc)"
say "Configuring and building $UV_BUILD/vtk (VTK $(dpkg-query -W -f='${Version}' libvtk9-dev))"
cmake -S "$UV_ROOT" -B "$UV_BUILD/vtk" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DUV_BUILD_PARAVIEW_PLUGIN=OFF >"$UV_BUILD/vtk-configure.log" 2>&1 ||
  { mkdir -p "$UV_BUILD"; cat "$UV_BUILD/vtk-configure.log"; exit 1; }
cmake --build "$UV_BUILD/vtk" -j "$jobs"

if [ -d "$paraview_cmake" ]; then
  say "Configuring and building $UV_BUILD/paraview (ParaView plugin)"
  cmake -S "$UV_ROOT" -B "$UV_BUILD/paraview" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 -DUV_BUILD_PARAVIEW_PLUGIN=ON >"$UV_BUILD/paraview-configure.log" 2>&1 ||
    { cat "$UV_BUILD/paraview-configure.log"; exit 1; }
  cmake --build "$UV_BUILD/paraview" -j "$jobs"
else
  say "ParaView not found: skipping the plugin build"
fi

export UV_PYTHONPATH="$UV_BUILD/vtk/lib/python3/dist-packages"
export UV_PLUGIN="$UV_BUILD/paraview/lib/paraview-plugins/UnstructuredVolume/UnstructuredVolume.so"
