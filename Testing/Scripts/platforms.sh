#!/usr/bin/env bash
# The platform matrix: builds and tests this source tree on Debian 13 (trixie: VTK 9.3, ParaView 5.13)
# and Debian testing (forky: VTK 9.6, ParaView 6.1), each in a chroot made with debootstrap from
# Debian's archive, by the same setup.sh and test.sh that run on Debian 12. Run as root.
#
#   bash Testing/Scripts/platforms.sh [tools|prepare|test|shell|run] [trixie] [forky]
#
# tools: install debootstrap on this machine (alone, so that parallel prepares need no apt); prepare: make (or reuse) the chroots and install their packages; test (default): prepare, then build
# into build/<suite>/ and run the platform subset (ctest label `platform`); shell: a shell in one;
# run: the command in $UV_RUN in each, from the source tree (to bisect a driver's failure).
# Chroots are kept in $UV_CHROOT_CACHE (default /var/cache/unstructuredvolume/chroots) and reused.
set -euo pipefail

UV_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cache="${UV_CHROOT_CACHE:-/var/cache/unstructuredvolume/chroots}"
mirror="${UV_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
action=test
case "${1:-}" in tools|prepare|test|shell|run) action="$1"; shift ;; esac
suites=("$@")
[ "${#suites[@]}" -gt 0 ] || suites=(trixie forky)

say() { printf '\n== [%s] %s\n' "$(date +%H:%M:%S)" "$*"; }
[ "$(id -u)" -eq 0 ] || { echo "platforms.sh makes and enters chroots: run it as root" >&2; exit 1; }

ensure_debootstrap() {
  command -v debootstrap >/dev/null && return
  apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap
}

# Debootstrap's script for a suite it may be too old to know: testing's releases all follow sid's.
debootstrap_script() {
  local scripts=/usr/share/debootstrap/scripts
  if [ -e "$scripts/$1" ]; then echo "$scripts/$1"; else echo "$scripts/sid"; fi
}

make_chroot() { # suite
  local suite="$1" root="$cache/$1"
  [ -x "$root/usr/bin/apt-get" ] && [ -f "$root/.uv-complete" ] && return
  ensure_debootstrap
  say "Making the $suite chroot in $root"
  rm -rf "$root"
  mkdir -p "$cache"
  debootstrap --variant=minbase "$suite" "$root" "$mirror" "$(debootstrap_script "$suite")" >"$cache/$suite-debootstrap.log" 2>&1 ||
    { tail -20 "$cache/$suite-debootstrap.log"; exit 1; }
  # Testing's Release file can outlive its Valid-Until between archive updates.
  echo 'Acquire::Check-Valid-Until "false";' >"$root/etc/apt/apt.conf.d/99uv-valid-until"
  echo "deb $mirror $suite main" >"$root/etc/apt/sources.list"
  touch "$root/.uv-complete"
}

mounted=()
mount_into() { # root
  local root="$1"
  mkdir -p "$root/uv/main" "$root/uv/shared"
  mount -t proc proc "$root/proc"; mounted+=("$root/proc")
  mount --rbind /dev "$root/dev"; mount --make-rslave "$root/dev"; mounted+=("$root/dev")
  mount -t sysfs sysfs "$root/sys"; mounted+=("$root/sys")
  mount --bind "$UV_ROOT" "$root/uv/main"; mounted+=("$root/uv/main")
  if [ -d "$UV_ROOT/../shared" ]; then
    mount --bind "$UV_ROOT/../shared" "$root/uv/shared"; mounted+=("$root/uv/shared")
  fi
  cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
}
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -R "${mounted[$i]}" 2>/dev/null || umount -l "${mounted[$i]}" || true; done
  mounted=()
}
trap unmount_all EXIT

in_chroot() { # suite, command...
  local suite="$1"; shift
  chroot "$cache/$suite" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 TERM="${TERM:-dumb}" UV_BUILD="/uv/main/build/$suite" UV_PLATFORM="$suite" "$@"
}

if [ "$action" = tools ]; then
  ensure_debootstrap
  exit 0
fi
status=0
for suite in "${suites[@]}"; do
  make_chroot "$suite"
  mount_into "$cache/$suite"
  case "$action" in
    prepare)
      say "Installing $suite's packages"
      in_chroot "$suite" bash /uv/main/Testing/Scripts/setup.sh --packages-only || status=1 ;;
    test)
      say "Building and testing on $suite"
      in_chroot "$suite" bash -c 'cd /uv/main && UV_TEST_LABEL=platform bash Testing/Scripts/test.sh' || status=1 ;;
    shell)
      in_chroot "$suite" bash -c 'cd /uv/main && exec bash -i' || status=1 ;;
    run)
      in_chroot "$suite" bash -c "cd /uv/main && $UV_RUN" || status=1 ;;
  esac
  unmount_all
  say "$suite: $([ "$status" -eq 0 ] && echo passed || echo FAILED so far)"
done
exit "$status"
