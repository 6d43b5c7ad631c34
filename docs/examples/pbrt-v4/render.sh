#!/bin/sh
# Exports the skin-fair preset as an RGL tensor file (spectral: the skin's own 31 wavelengths) beside
# skin-sphere.pbrt and renders the scene with pbrt-v4 (not part of skinlayer: build it from its own sources and put
# `pbrt` on PATH, or set PBRT=/path/to/pbrt).
# Usage: docs/examples/pbrt-v4/render.sh [path/to/skinlayer]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
skinlayer=${1:-$here/../../../build/skinlayer}
"$skinlayer" export --format rgl --preset skin-fair -o "$here/skin.bsdf"
pbrt=${PBRT:-pbrt}
if ! command -v "$pbrt" >/dev/null 2>&1; then
  echo "wrote $here/skin.bsdf; pbrt-v4 is not on PATH (set PBRT=/path/to/pbrt), so nothing is rendered" >&2
  exit 0
fi
cd "$here" && "$pbrt" skin-sphere.pbrt
