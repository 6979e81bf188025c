#!/usr/bin/env bash
# `make demo`: runs the main job on a bundled real drawing and writes its
# outputs under out/. Each later stage extends what this runs.
set -euo pipefail
build=${1:-build}
cd "$(dirname "$0")/.."
bin="$build/ui/cli/hair25d"
sample=samples/wikipe-tan
mkdir -p out
echo "hair25d demo: segmenting $sample/image.png with $sample/strokes.json"
"$bin" segment "$sample/image.png" --strokes "$sample/strokes.json" -o out/demo-segment
echo "wrote out/demo-segment/overlay.png (curves, mesh, regions) and regions.png"
if "$bin" --help 2>/dev/null | grep -q '^  model'; then
  echo "hair25d demo: building the 2.5D model"
  "$bin" model "$sample/image.png" --strokes "$sample/strokes.json" -o out/demo-model
  echo "wrote out/demo-model/ (model.json, textures, contact_sheet.png)"
fi
