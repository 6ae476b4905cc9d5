#!/usr/bin/env bash
# The README's animation: Examples/Scenes/smoke_plume.json simulated with
# `plume simulate` (every 4th of 120 steps), each step rendered by `plume
# render` (volume mapper + velocity glyph lines, Examples/Animation/
# smoke_plume_frame.json) and the frames assembled into a GIF by ffmpeg.
#   bash scripts/make-smoke-animation.sh [OUT.gif]   (default Documentation/images/smoke_plume.gif)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/Documentation/images/smoke_plume.gif}"
plume="${PLUME:-$root/build/bin/plume}"
command -v ffmpeg >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -q ffmpeg
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$plume" simulate "$root/Examples/Scenes/smoke_plume.json" -o "$work/smoke_plume.pvd" --every 4
steps=$(grep -c "<DataSet" "$work/smoke_plume.pvd")
for ((i = 0; i < steps; ++i)); do
  sed "s/\"time_step\": 0/\"time_step\": $i/" "$root/Examples/Animation/smoke_plume_frame.json" > "$work/frame.json"
  "$plume" render "$work/frame.json" -o "$(printf "$work/frame_%03d.png" "$i")" 2>/dev/null
done
# one palette for all frames keeps the smoke's greys smooth
ffmpeg -loglevel error -y -framerate 10 -i "$work/frame_%03d.png" \
  -vf "split[a][b];[a]palettegen=max_colors=128[p];[b][p]paletteuse=dither=bayer:bayer_scale=3" -loop 0 "$out"
echo "wrote $out ($steps frames)"
