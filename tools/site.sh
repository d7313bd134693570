#!/usr/bin/env bash
# Builds the static site (page, wasm, scenes, assets) into one folder, as GitHub Pages
# publishes it (.github/workflows/pages.yml runs this script):
#   bash tools/site.sh [OUT]       OUT defaults to build/site
# With Debian's Emscripten (here): installs what is missing and uses the web preset. With
# the upstream SDK ($EMSDK set, as in the workflow): configures build/web-emsdk with its
# toolchain (the libraries come through FetchContent). Every URL in the page is relative,
# so the folder works from any sub-path (https://USER.github.io/REPO/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out="${1:-build/site}"
if [[ -n "${EMSDK:-}" ]]; then
  build=build/web-emsdk
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPT_BUILD_TESTS=OFF \
    -DCMAKE_TOOLCHAIN_FILE="$EMSDK/upstream/emscripten/cmake/Modules/Platform/Emscripten.cmake" >/dev/null
  cmake --build "$build"
else
  build=build/web
  bash tools/deps.sh web
  export NODE_PATH=/usr/share/nodejs
  cmake --preset web >/dev/null
  cmake --build --preset web
fi
rm -rf "$out"
mkdir -p "$out"
cp "$build"/{index.html,style.css,files.js,pathtracer.js,pathtracer.wasm,pathtracer.data} "$out/"
cp -r scenes assets "$out/"
touch "$out/.nojekyll"  # serve files as they are
echo "site: $out ($(du -sh "$out" | cut -f1)); try it: node tools/serve.mjs $out 8000 --base /pathtracer/"
