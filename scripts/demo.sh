#!/usr/bin/env bash
# Set-up command 1: install what is missing, build, and render the main demo
# (velocity glyph lines in the carotid artery, real CFD data) to demo/carotid_glyphs.png.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_BUILD_DIR:-$root/build}"
bash "$root/scripts/build.sh"
mkdir -p "$root/demo"
out="$root/demo/carotid_glyphs.png"
# No X server needed: plume renders through an in-process OSMesa context.
"$build/bin/plume" render "$root/Examples/Scenes/carotid_glyphs.json" -o "$out"
echo "demo image: $out"
