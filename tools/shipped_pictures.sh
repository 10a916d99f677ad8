#!/usr/bin/env bash
# The README's pictures: runs every shipped scene into results/SCENE, writes its report
# (tools/report.py) and copies its strain maps into docs/pictures/SCENE_strain_{warp,weft}.png
# (and a run in load steps its strain and draw-in against travel, SCENE_steps.png), and the cup's
# 3-D view as headless Chromium draws it (docs/pictures/cup_view3d.png).
# Run after tools/setup.sh; takes about two minutes on two cores.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mkdir -p docs/pictures
for scene in mold vacuum cup torso torso_frictionless dome; do
  status=0
  build/fabform run "scenes/$scene.toml" --out "results/$scene" --quiet || status=$?
  if [[ $status -ne 0 && $status -ne 3 ]]; then exit "$status"; fi
  /usr/bin/python3 tools/report.py "results/$scene"
  for direction in warp weft; do
    cp "results/$scene/strain_$direction.png" "docs/pictures/${scene}_strain_$direction.png"
  done
  if [[ -f "results/$scene/steps.png" ]]; then cp "results/$scene/steps.png" "docs/pictures/${scene}_steps.png"; fi
done
# The README's picture: the cup's report, its 3-D view alone, as headless Chromium (software WebGL) draws it.
profile=$(mktemp -d)
chromium --headless --no-sandbox --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader \
  --user-data-dir="$profile" --hide-scrollbars --window-size=900,700 --virtual-time-budget=10000 \
  --screenshot="$PWD/docs/pictures/cup_view3d.png" "file://$PWD/results/cup/report.html#field=strain_warp&alone" 2>/dev/null
rm -rf "$profile"
