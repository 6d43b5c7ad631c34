#!/bin/sh
# Fails unless git ignores every file that a skinlayer command writes where no path is given:
#   skinlayer validate              -> validation/ (validation.md, one PNG per set)
#   the previewer's Screenshot      -> skinlayer-YYYYMMDD-HHMMSS.png in the current folder
#   the previewer's Export buttons  -> the same name with .bsdf or .binary
#   docs/examples/*/render.sh        -> skin.bsdf and the renderer's picture beside each scene
# Run from the repository's root with git's path as $1. Exit 77 (skipped) outside a git work tree.
git=$1
"$git" rev-parse --is-inside-work-tree >/dev/null 2>&1 || exit 77
status=0
for path in validation/validation.md validation/thin-sharp.png \
            skinlayer-20261201-235959.png skinlayer-20261201-235959.bsdf skinlayer-20261201-235959.binary \
            app/skinlayer-20261201-235959.png \
            docs/examples/pbrt-v3/skin.bsdf docs/examples/pbrt-v3/skin-sphere.png \
            docs/examples/pbrt-v4/skin.bsdf docs/examples/pbrt-v4/skin-sphere.png \
            docs/examples/mitsuba3/skin.bsdf docs/examples/mitsuba3/skin-sphere.exr; do
  if ! "$git" check-ignore -q --no-index "$path"; then
    echo "not ignored by git: $path"
    status=1
  fi
done
exit $status
