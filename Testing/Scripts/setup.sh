#!/usr/bin/env bash
# Installs what the project needs from the distribution (Debian 12, 13 or testing: whatever VTK and
# ParaView it has) and builds it twice: build/vtk (the system VTK + Python) and build/paraview (the
# ParaView plugin). Idempotent: re-running only rebuilds. Sourced by main.sh and test.sh; exports
# UV_* variables describing the builds. `setup.sh --packages-only` installs and stops.
set -euo pipefail

UV_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
UV_BUILD="${UV_BUILD:-$UV_ROOT/build}"
export UV_ROOT UV_BUILD

say() { printf '\n== %s\n' "$*"; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

packages=(
  cmake ninja-build g++ pkg-config
  libvtk9-dev python3-vtk9 python3-dev
  paraview paraview-dev mpi-default-bin
  libglm-dev googletest libgtest-dev
  glslang-tools  # glslangValidator: the composed GLSL against the specification
  xvfb xauth
  x11-apps imagemagick  # xwd and convert: the ParaView GUI test's screenshot
)
installed() { [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" == *"install ok installed"* ]]; }
lists_updated=0
update_lists() { # once per run: the choices below read the package lists, the install needs them
  [ "$lists_updated" -eq 1 ] || { as_root apt-get update -q; lists_updated=1; }
}
# ParaView's CMake package looks for the Qt it was built with: Qt 5 up to Debian 12's 5.11, Qt 6 since.
installed paraview || update_lists
paraview_depends="$(apt-cache depends paraview 2>/dev/null || true)" # not piped into grep -q: pipefail
if [[ "$paraview_depends" == *libqt6* ]]; then
  packages+=(qt6-base-dev qt6-tools-dev qt6-svg-dev qt6-5compat-dev xsltproc) # xsltproc: Qt 6 has no xmlpatterns
else
  packages+=(qtbase5-dev qttools5-dev qtxmlpatterns5-dev-tools libqt5opengl5-dev libqt5svg5-dev)
fi
# ParaView's Python: where Debian's python3-paraview conflicts with python3-vtk9 (up to ParaView 5.13,
# which bundle their own VTK), it is unpacked privately under this prefix (see below) and pvbatch
# finds it through PYTHONPATH; since ParaView 6 (built on the system's VTK) it installs as usual.
if [[ "$(apt-cache show python3-paraview 2>/dev/null || true)" == *"Conflicts: "*python3-vtk9* ]]; then
  UV_PARAVIEW_PYTHON_PREFIX=/opt/unstructuredvolume/paraview-python
else
  UV_PARAVIEW_PYTHON_PREFIX=
  packages+=(python3-paraview)
fi
UV_PARAVIEW_PYTHONPATH="$UV_PARAVIEW_PYTHON_PREFIX/usr/lib/python3/dist-packages"
export UV_PARAVIEW_PYTHON_PREFIX UV_PARAVIEW_PYTHONPATH
missing=()
for package in "${packages[@]}"; do
  installed "$package" || missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  say "Installing ${missing[*]}"
  update_lists
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  say "Debian packages already installed"
fi

# Debian's python3-paraview conflicts with python3-vtk9 (both ship vtkmodules/), yet pvbatch needs
# the former and libvtk9-dev the latter. So python3-paraview is unpacked privately, and pvbatch and
# pvpython get it through PYTHONPATH. ParaView's CMake package also checks that the files of its
# imported targets exist: those that python3-paraview would have installed (its Python modules, and
# bin/pvpython) are linked into place from the private copy. The targets name the modules untagged
# (vtkCommonCore.so); 5.11 ships them so, 5.13 and 6.1 (whose python3-paraview installs as usual)
# ship them cpython-tagged, so there the untagged name links to the tagged file. Python prefers a
# tagged name over an untagged one, so /usr/bin/python3 still imports Debian's VTK.
if [ -n "$UV_PARAVIEW_PYTHON_PREFIX" ] && [ ! -f "$UV_PARAVIEW_PYTHONPATH/paraview/simple.py" ]; then
  say "Unpacking python3-paraview into $UV_PARAVIEW_PYTHON_PREFIX"
  download_dir="$(mktemp -d)"
  chmod 755 "$download_dir"
  (cd "$download_dir" && apt-get download python3-paraview)
  as_root mkdir -p "$UV_PARAVIEW_PYTHON_PREFIX"
  as_root dpkg -x "$download_dir"/python3-paraview_*.deb "$UV_PARAVIEW_PYTHON_PREFIX"
  rm -rf "$download_dir"
fi
# pvpython in the private copy puts the dist-packages beside its executable first, so it runs without
# PYTHONPATH; copies of pvbatch and the GUI placed beside it do the same (tested with the installed
# plugin). ParaView reads paraview.conf beside its executable up to 5.11: linked after the install.
if [ -n "$UV_PARAVIEW_PYTHON_PREFIX" ]; then
  for executable in pvbatch paraview; do
    cmp -s "$(command -v $executable)" "$UV_PARAVIEW_PYTHON_PREFIX/usr/bin/$executable" ||
      as_root cp -L "$(command -v $executable)" "$UV_PARAVIEW_PYTHON_PREFIX/usr/bin/$executable"
  done
fi
# ParaView's CMake package, of whichever version the distribution has.
paraview_cmake="$(ls -d /usr/lib/*/cmake/paraview-* 2>/dev/null | sort -V | tail -1)"
link_missing() { # relative paths under /usr, on standard input
  while read -r relative; do
    target="/usr/$relative"
    source="$UV_PARAVIEW_PYTHON_PREFIX/usr/$relative"
    if [ ! -e "$source" ] && [[ "$relative" == *.so ]]; then
      source="$(ls "${source%.so}".cpython-*.so 2>/dev/null | head -1 || true)"
    fi
    if [ ! -e "$target" ] && [ -e "$source" ]; then
      as_root mkdir -p "$(dirname "$target")"
      as_root ln -sf "$source" "$target"
      linked=$((linked + 1))
    fi
  done
}
linked=0
# Files ParaView's imported targets name, and its wrapping hierarchy files (not Python packages).
[ -z "$paraview_cmake" ] ||
link_missing < <(grep -ho '"${_IMPORT_PREFIX}/[^"]*"' "$paraview_cmake"/*-targets-*.cmake "$paraview_cmake"/vtk/*-targets-*.cmake |
                 sed 's/"${_IMPORT_PREFIX}\///; s/"$//' | sort -u)
[ -z "$UV_PARAVIEW_PYTHON_PREFIX" ] ||
link_missing < <(cd "$UV_PARAVIEW_PYTHON_PREFIX/usr" && find . -type f -not -path './lib/python3/*' | sed 's|^\./||')
[ "$linked" -eq 0 ] || say "Linked $linked files of python3-paraview for ParaView's CMake package"

[ "${1:-}" != --packages-only ] || return 0 2>/dev/null || exit 0

mkdir -p "$UV_BUILD"
jobs="$(nproc)"
say "Configuring and building $UV_BUILD/vtk (VTK $(dpkg-query -W -f='${Version}' libvtk9-dev))"
cmake -S "$UV_ROOT" -B "$UV_BUILD/vtk" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DUV_BUILD_PARAVIEW_PLUGIN=OFF >"$UV_BUILD/vtk-configure.log" 2>&1 ||
  { mkdir -p "$UV_BUILD"; cat "$UV_BUILD/vtk-configure.log"; exit 1; }
cmake --build "$UV_BUILD/vtk" -j "$jobs"

if [ -n "$paraview_cmake" ]; then
  say "Configuring and building $UV_BUILD/paraview (ParaView $(dpkg-query -W -f='${Version}' paraview-dev) plugin)"
  cmake -S "$UV_ROOT" -B "$UV_BUILD/paraview" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 -DUV_BUILD_PARAVIEW_PLUGIN=ON \
    -DUV_PARAVIEW_PYTHON_PREFIX="$UV_PARAVIEW_PYTHON_PREFIX" >"$UV_BUILD/paraview-configure.log" 2>&1 ||
    { cat "$UV_BUILD/paraview-configure.log"; exit 1; }
  cmake --build "$UV_BUILD/paraview" -j "$jobs"
else
  say "ParaView not found: skipping the plugin build"
fi

# Installed as a user would: the Python package where VTK's Python finds it, the plugin in ParaView's
# plugin folder and listed in its paraview.conf (CMakeLists.txt, Plugin/RegisterPlugin.cmake).
say "Installing both builds (cmake --install)"
as_root cmake --install "$UV_BUILD/vtk" >"$UV_BUILD/vtk-install.log"
if [ -n "$paraview_cmake" ]; then
  as_root cmake --install "$UV_BUILD/paraview" >"$UV_BUILD/paraview-install.log"
  if [ -n "$UV_PARAVIEW_PYTHON_PREFIX" ] && [ -f /usr/bin/paraview.conf ]; then
    as_root ln -sf /usr/bin/paraview.conf "$UV_PARAVIEW_PYTHON_PREFIX/usr/bin/paraview.conf"
  fi
fi

export UV_PYTHONPATH="$UV_BUILD/vtk/lib/python3/dist-packages"
UV_PLUGIN="$(ls "$UV_BUILD"/paraview/lib/*/paraview-*/plugins/UnstructuredVolume/UnstructuredVolume.so \
  "$UV_BUILD"/paraview/lib/paraview-*/plugins/UnstructuredVolume/UnstructuredVolume.so 2>/dev/null | head -1 || true)"
export UV_PLUGIN
