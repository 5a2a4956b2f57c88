# SPDX-License-Identifier: LGPL-2.1-or-later
# Sourced by scripts/test-debian13 and scripts/test-package: Debian roots made with
# debootstrap from Debian's archive through debootstrap's default mirror, cached under
# $SLICEFORM_CACHE (default /var/cache/sliceform, outside the repository), and the mounts a
# chroot needs. Every mount made here is recorded and undone by root_cleanup, which the
# caller runs from an EXIT trap (root_trap), so no exit path leaves one behind.

SLICEFORM_CACHE=${SLICEFORM_CACHE:-/var/cache/sliceform}
_root_mounts=()   # mount points, in the order they were made
_root_temps=()    # folders to remove after the mounts are gone

# Runs this script again as root (chroot and mount need it).
root_need_root() {
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "$(basename "$0"): needs root (or sudo) for chroot and mount" >&2; exit 1; }
    exec sudo --preserve-env=SLICEFORM_CACHE,SLICEFORM_DEBIAN13_ROOT "$0" "$@"
  fi
}

root_cleanup() {
  local i status=0
  for ((i = ${#_root_mounts[@]} - 1; i >= 0; i--)); do
    local m=${_root_mounts[i]}
    if mountpoint -q "$m"; then
      umount "$m" 2>/dev/null || umount -l "$m" || { echo "cannot unmount $m" >&2; status=1; }
    fi
  done
  _root_mounts=()
  for t in "${_root_temps[@]}"; do
    # Nothing is removed while anything below it is still mounted.
    local left
    left=$(awk -v t="$t/" 'index($2 "/", t) == 1 { print $2 }' /proc/mounts | sort -r)
    for m in $left; do umount "$m" 2>/dev/null || umount -l "$m" || status=1; done
    if awk -v t="$t/" 'index($2 "/", t) == 1 { found = 1 } END { exit !found }' /proc/mounts; then
      echo "still mounted below $t: not removed" >&2
      status=1
    else
      rm -rf --one-file-system "$t"
    fi
  done
  _root_temps=()
  return $status
}

root_trap() {
  trap 'root_cleanup' EXIT
  trap 'exit 130' INT
  trap 'exit 143' TERM
}

_root_mount() {  # mount ARGS... TARGET
  mount "$@"
  _root_mounts+=("${!#}")
}

# root_base RELEASE: a minimal root of RELEASE (bookworm, trixie) at
# $SLICEFORM_CACHE/RELEASE/base, made once and never changed after (the clean roots of the
# package tests are overlays on it). Prints its path.
root_base() {
  local release=$1 dir="$SLICEFORM_CACHE/$1/base"
  if [[ ! -f "$dir/.sliceform-complete" ]]; then
    if ! command -v debootstrap >/dev/null; then
      echo "installing debootstrap" >&2
      DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null ||
        { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null; }
    fi
    echo "debootstrap --variant=minbase $release (about a minute)" >&2
    rm -rf --one-file-system "$dir.partial"
    mkdir -p "$(dirname "$dir")"
    debootstrap --variant=minbase "$release" "$dir.partial" >"$SLICEFORM_CACHE/$release/debootstrap.log" 2>&1 ||
      { tail -20 "$SLICEFORM_CACHE/$release/debootstrap.log" >&2; return 1; }
    # apt keeps what it downloads, so a second install in a root made from this one reads
    # the packages from the cache instead of the network.
    rm -f "$dir.partial/etc/apt/apt.conf.d/docker-clean"
    touch "$dir.partial/.sliceform-complete"
    rm -rf --one-file-system "$dir"
    mv "$dir.partial" "$dir"
  fi
  echo "$dir"
}

# root_enter ROOT: /proc, /dev and /dev/pts for a chroot into ROOT, the host's DNS, and
# dpkg without fsync.
root_enter() {
  local root=$1
  _root_mount -t proc proc "$root/proc"
  _root_mount --bind /dev "$root/dev"
  _root_mount --bind /dev/pts "$root/dev/pts"
  cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
  # These roots are caches or thrown away: dpkg need not sync every file it unpacks (the
  # few hundred packages of FreeCAD).
  echo force-unsafe-io >"$root/etc/dpkg/dpkg.cfg.d/sliceform-unsafe-io"
}

# root_overlay BASE ARCHIVES: a throwaway root whose changes go to a temporary folder over
# the untouched BASE; apt's package cache is ARCHIVES (kept between runs). Sets ROOT_OVERLAY
# to the root (not printed: the mounts must be recorded in this shell, not a subshell).
root_overlay() {
  local base=$1 archives=$2 tmp
  tmp=$(mktemp -d "$SLICEFORM_CACHE/overlay.XXXXXX")
  _root_temps+=("$tmp")
  mkdir -p "$tmp/upper" "$tmp/work" "$tmp/root" "$archives"
  _root_mount -t overlay overlay -o "lowerdir=$base,upperdir=$tmp/upper,workdir=$tmp/work" "$tmp/root"
  _root_mount --bind "$archives" "$tmp/root/var/cache/apt/archives"
  ROOT_OVERLAY="$tmp/root"
}

# root_run ROOT COMMAND...: COMMAND inside ROOT, with a plain environment.
root_run() {
  local root=$1
  shift
  chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    HOME=/root LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"
}
