#!/bin/bash
# Runs the Blender of a chroot made by make_blender_chroot.sh, so that host paths work unchanged inside it:
#
#   sudo tests/app/export/blender_in_chroot.sh DIR [blender args...]
#   e.g. blender_in_chroot.sh build-blender/sid -b --python-exit-code 1 --python /tmp/x.py
#
# Inside the chroot /proc, /dev and /sys (read-only) are mounted: Blender reads /proc/meminfo and /proc/self/exe,
# /dev/null and /dev/urandom, and its thread pool sizes itself from /sys/devices/system/cpu/online, the NUMA nodes
# and the cgroup's CPU quota. The host's /tmp, this repository and the current folder appear at the same absolute
# paths, and the command runs in the current folder, so host paths, absolute or relative, work unchanged. Files
# anywhere else on the host are not visible: put them under /tmp or the repository. Empty mount point folders are
# left in the chroot (e.g. DIR/work/...). The environment is cleared except PATH, HOME=/root, LANG and TERM.
#
# The mounts are made in a private mount namespace (unshare --mount): they are never visible on the host, two runs
# at the same time each get their own, and the kernel drops them when the run ends, even if it is killed; they are
# also unmounted explicitly on exit. Needs root. The exit status is Blender's.
set -euo pipefail

die() {
  echo "blender_in_chroot: $*" >&2
  exit 125
}

if [[ ${_BLENDER_IN_CHROOT_NS:-} != 1 ]]; then
  [[ $# -ge 1 ]] || die "usage: $0 DIR [blender args...]"
  [[ $(id -u) -eq 0 ]] || die "must run as root (chroot and mount need it)"
  [[ -d $1 ]] || die "no chroot folder $1 (make one with make_blender_chroot.sh)"
  dir=$(cd "$1" && pwd -P)
  [[ -x $dir/usr/bin/blender ]] || die "$dir has no /usr/bin/blender (make it with make_blender_chroot.sh)"
  command -v unshare > /dev/null || die "unshare (util-linux) not found"
  shift
  # If mount namespaces are refused here, unshare says so and the run fails with its status.
  _BLENDER_IN_CHROOT_NS=1 exec unshare --mount --propagation private -- "$BASH" "${BASH_SOURCE[0]}" "$dir" "$@"
fi

# From here on: inside the private mount namespace.
dir=$1
shift
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd -P)
cwd=$(pwd -P)

mounted=()
# shellcheck disable=SC2317 # called by the trap
unmount_all() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount -R -l "${mounted[i]}" 2> /dev/null || true
  done
}
trap unmount_all EXIT

# Binds host path $1 at the same path inside the chroot (mount type in $2: proc, rbind, rbind-ro or bind).
mount_at() {
  local target=$dir$1
  mkdir -p "$target"
  case $2 in
    proc) mount -t proc proc "$target" ;;
    rbind) mount --rbind "$1" "$target" ;;
    rbind-ro) mount --rbind "$1" "$target" && mount -o remount,bind,ro "$target" ;;
    bind) mount --bind "$1" "$target" ;;
  esac || die "could not mount $1 at $target"
  mounted+=("$target")
}

# True when $1 is $2 or below it.
is_below() { [[ $1 == "$2" || $1 == "$2"/* ]]; }

mount_at /proc proc
mount_at /dev rbind
mount_at /sys rbind-ro
mount_at /tmp bind
is_below "$repo_root" /tmp || mount_at "$repo_root" bind
if [[ $cwd != / ]] && ! is_below "$cwd" /tmp && ! is_below "$cwd" "$repo_root"; then
  is_below "$cwd" /proc || is_below "$cwd" /dev || is_below "$cwd" /sys || mount_at "$cwd" bind
fi

rc=0
# shellcheck disable=SC2016 # $1 and $@ belong to the inner shell
chroot "$dir" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 TERM="${TERM:-dumb}" \
  /bin/sh -c 'cd "$1" || exit 125; shift; exec blender "$@"' sh "$cwd" "$@" || rc=$?
exit "$rc"
