#!/bin/sh
# Exports the skin-fair preset as an RGL tensor file beside skin-sphere.xml and renders the scene with Mitsuba 3 (not
# part of skinlayer: install it from its own sources or package and put `mitsuba` on PATH, or set
# MITSUBA=/path/to/mitsuba). VARIANT picks Mitsuba's variant (default scalar_spectral); an RGB variant gets the rgb
# form, which is the one its RGB variants read.
# Usage: [VARIANT=scalar_rgb] docs/examples/mitsuba3/render.sh [path/to/skinlayer]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
skinlayer=${1:-$here/../../../build/skinlayer}
variant=${VARIANT:-scalar_spectral}
case "$variant" in
  *rgb*) "$skinlayer" export --format rgl --rgb --preset skin-fair -o "$here/skin.bsdf" ;;
  *) "$skinlayer" export --format rgl --preset skin-fair -o "$here/skin.bsdf" ;;
esac
mitsuba=${MITSUBA:-mitsuba}
if ! command -v "$mitsuba" >/dev/null 2>&1; then
  echo "wrote $here/skin.bsdf; Mitsuba 3 is not on PATH (set MITSUBA=/path/to/mitsuba), so nothing is rendered" >&2
  exit 0
fi
cd "$here" && "$mitsuba" -m "$variant" -o skin-sphere.exr skin-sphere.xml
