#!/bin/bash
# Builds a minimal Debian chroot with that release's Blender, so the exported Blender script can be checked against
# newer Blender versions than the host's (Debian 12 ships 3.4; trixie 4.3, sid 5.x).
#
#   sudo tests/app/export/make_blender_chroot.sh SUITE [DIR]
#
# SUITE: trixie or sid (any suite debootstrap knows works). DIR defaults to build-blender/SUITE at the repository
# root (ignored by git). Run Blender in it with tests/app/export/blender_in_chroot.sh DIR [blender args...].
#
# Needs root and debootstrap (apt-get install debootstrap). The Debian mirror is the one this machine's apt uses
# (read from /etc/apt/sources.list and /etc/apt/sources.list.d at run time); MIRROR=... overrides it.
# Idempotent: when DIR already holds a Blender that starts, it says so and exits 0. An interrupted debootstrap is
# started over; an interrupted package install is resumed.
#
# Measured from an empty DIR (2 shared cores, Debian 12 host, mirror at ~100-200 MB/s, December 2026):
#   trixie (Blender 4.3.2):     79-86 s (two runs), 1.35 GB (354 packages, 295 MB downloaded for Blender)
#   sid    (Blender 5.2.2 LTS): 72-93 s (two runs), 1.0 GB  (241 packages, 219 MB downloaded for Blender)
# debootstrap itself is ~40 s of that; apt's package cache is emptied afterwards.
set -euo pipefail
{ # One block, read whole before it runs: editing this file during a run does not derail it.

die() {
  echo "make_blender_chroot: $*" >&2
  exit 1
}

[[ $# -ge 1 && $# -le 2 ]] || die "usage: $0 SUITE [DIR]  (SUITE: trixie or sid)"
suite=$1
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd -P)
dir=${2:-$repo_root/build-blender/$suite}

[[ $(id -u) -eq 0 ]] || die "must run as root (debootstrap and chroot need it)"
command -v unshare > /dev/null || die "unshare (util-linux) not found"

mkdir -p "$dir"
dir=$(cd "$dir" && pwd -P)

# Runs a command inside the chroot with /proc, /sys and /dev mounted in a private mount namespace: the mounts
# vanish with the command, whatever happens, and never show in the host's mount table.
in_chroot() {
  # shellcheck disable=SC2016 # $1 and $@ belong to the inner shell
  unshare --mount --propagation private -- /bin/sh -c '
    d=$1; shift
    mount -t proc proc "$d/proc" && mount --rbind /sys "$d/sys" && mount --rbind /dev "$d/dev" &&
      exec chroot "$d" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
        DEBIAN_FRONTEND=noninteractive "$@"' sh "$dir" "$@"
}

# Works: Blender starts in the background, runs Python and prints no traceback (a missing module of its own
# scripts shows as one). Sets $version.
version=
blender_works() {
  local out
  [[ -x $dir/usr/bin/blender ]] || return 1
  out=$(in_chroot blender -b --factory-startup --python-exit-code 1 \
    --python-expr 'import bpy; print("BLENDER_VERSION", bpy.app.version_string)' 2>&1) || return 1
  grep -q Traceback <<< "$out" && return 1
  version=$(sed -n 's/^BLENDER_VERSION //p' <<< "$out")
  [[ -n $version ]]
}

if blender_works; then
  echo "make_blender_chroot: $dir already has a working Blender $version"
  exit 0
fi

command -v debootstrap > /dev/null || die "debootstrap not found; install it with: apt-get install debootstrap"
[[ -e /usr/share/debootstrap/scripts/$suite ]] || die "debootstrap does not know suite '$suite'"

# The mirror this machine's apt uses: the first deb source whose URI ends in /debian (not -security, not
# third-party). One-line *.list files and deb822 *.sources files are both read.
find_mirror() {
  local f
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [[ -r $f ]] || continue
    # deb [option=value ...] URI suite components: the URI is the first word after the bracketed options.
    awk '$1 == "deb" {
      i = 2
      if ($i ~ /^\[/) { while (i <= NF && $i !~ /\]$/) i++; i++ }
      if (i <= NF) print $i
    }' "$f"
  done
  for f in /etc/apt/sources.list.d/*.sources; do
    [[ -r $f ]] || continue
    awk 'tolower($1) == "uris:" { for (i = 2; i <= NF; i++) print $i }' "$f"
  done
}
mirror=${MIRROR:-$(find_mirror | sed 's:/*$::' | grep -E '/debian$' | head -n 1 || true)}
[[ -n $mirror ]] || die "no Debian mirror found in /etc/apt/sources.list(.d); set MIRROR=http://.../debian"

# The finished chroot takes 1.0-1.4 GB; apt's downloads (~300 MB) need room on top while it installs.
need_kb=$((3 * 1024 * 1024))
free_kb=$(df -Pk "$dir" | awk 'NR == 2 { print $4 }')
((free_kb >= need_kb)) || die "not enough space in $dir: $((free_kb / 1024)) MiB free, need $((need_kb / 1024)) MiB"

mounted_below() { awk -v d="$dir" '$2 == d || index($2, d "/") == 1' /proc/self/mounts | grep -q .; }

start=$(date +%s)
if [[ -d $dir/debootstrap || ! -x $dir/usr/bin/apt-get ]]; then
  # Absent, empty or left half-done by an interrupted debootstrap: start over.
  mounted_below && die "something is mounted below $dir; unmount it first"
  if [[ -n $(ls -A "$dir") ]]; then
    echo "make_blender_chroot: removing the incomplete chroot in $dir"
    rm -rf --one-file-system "${dir:?}"/*
  fi
  echo "make_blender_chroot: debootstrap $suite (minbase) into $dir from $mirror"
  debootstrap --variant=minbase "$suite" "$dir" "$mirror" ||
    die "debootstrap failed (its log: $dir/debootstrap/debootstrap.log)"
fi

echo "make_blender_chroot: installing blender (no recommends) from $suite"
# The mirror may be a frozen snapshot whose Release file has passed its Valid-Until date (sid's lasts a week);
# debootstrap does not check that date, apt does. The packages are still signed, so only the date check goes.
echo 'Acquire::Check-Valid-Until "false";' > "$dir/etc/apt/apt.conf.d/99snapshot-mirror"
in_chroot apt-get update -q || die "apt-get update failed in the chroot"
in_chroot apt-get install -y -q --no-install-recommends blender || die "apt-get install blender failed in the chroot"

# Blender's bundled scripts import modules Debian's package does not depend on (sid's 5.2: the extensions add-on
# imports cattrs, requests and urllib3 at startup and prints a traceback without them). Install those the scripts
# import and the chroot's Python lacks.
extra=()
for pair in cattrs:python3-cattr requests:python3-requests urllib3:python3-urllib3; do
  module=${pair%%:*}
  grep -rqE "^\s*import $module\b" "$dir/usr/share/blender/scripts" 2> /dev/null || continue
  in_chroot python3 -c "import $module" 2> /dev/null || extra+=("${pair#*:}")
done
if ((${#extra[@]})); then
  echo "make_blender_chroot: installing Python modules Blender's scripts import: ${extra[*]}"
  in_chroot apt-get install -y -q --no-install-recommends "${extra[@]}" || die "apt-get install ${extra[*]} failed"
fi
in_chroot apt-get clean
# Blender lists mounted file systems from /etc/mtab (a warning at every start without it); minbase has none.
[[ -e $dir/etc/mtab || -L $dir/etc/mtab ]] || ln -s ../proc/self/mounts "$dir/etc/mtab"

blender_works || die "blender is installed in $dir but fails to start cleanly; see: $(dirname "$0")/blender_in_chroot.sh $dir -b"
echo "make_blender_chroot: Blender $version ready in $dir (this run $(($(date +%s) - start)) s," \
  "$(du -sh --one-file-system "$dir" | cut -f 1))"
exit 0
}
