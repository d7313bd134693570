#!/usr/bin/env bash
# Renders every shipped scene (except the benchmark mesh) to docs/img/scenes/ for
# docs/scenes.md: 480x270, SPP samples (default 256), default settings.
#   bash tools/scene_gallery.sh            (after cmake --build --preset native)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=docs/img/scenes
mkdir -p "$out"
for s in $(find scenes -name '*.xml' -not -path 'scenes/bench/*' | sort); do
  n=$(echo "${s#scenes/}" | sed 's#/#-#g; s#\.xml$##')
  build/native/pathtracer render "$s" --size 480x270 --spp "${SPP:-256}" --out "$out/$n.png" | grep -E "rendered"
done
