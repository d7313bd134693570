#!/usr/bin/env bash
# README command (2): install what is missing, build, run every test.
#   bash tools/test.sh            native unit + GPU tests (llvmpipe), CLI tests, browser test
#   PT_SKIP_BROWSER=1 bash tools/test.sh   native tests only
#   PT_SKIP_SANITIZERS=1                    skip the ASan/UBSan suite and the fuzzers
#   PT_FUZZ_SECONDS=N                       seconds per fuzz target (default 30)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
start=$(date +%s)
# Each phase's start is printed with the seconds since the start (CI's budget is 30 min).
phase() { echo "== [$(( $(date +%s) - start )) s] $*"; }
bash tools/deps.sh "${PT_SKIP_BROWSER:+native}"
phase "layers point down (includes under src/)"
python3 tools/check_layers.py
phase "native build"
cmake --preset native >/dev/null
cmake --build --preset native
phase "native tests (GL: Mesa llvmpipe unless a GPU is present)"
ctest --preset native -j2
if [[ -z "${PT_SKIP_SANITIZERS:-}" ]]; then
  phase "native tests under AddressSanitizer + UndefinedBehaviorSanitizer (leaks included), GL checks on"
  t0=$(date +%s)
  cmake --preset native-asan >/dev/null
  cmake --build --preset native-asan
  ctest --preset native-asan -j2
  echo "== sanitizer build and suite: $(( $(date +%s) - t0 )) s"
  phase "fuzzers (docs/reliability.md)"
  t0=$(date +%s)
  PT_FUZZ_SECONDS="${PT_FUZZ_SECONDS:-30}" bash tools/fuzz.sh
  echo "== fuzz build and runs: $(( $(date +%s) - t0 )) s"
fi
if [[ -z "${PT_SKIP_BROWSER:-}" ]]; then
  phase "web build"
  export NODE_PATH=/usr/share/nodejs
  cmake --preset web >/dev/null
  cmake --build --preset web
  phase "browser test (headless Chromium, WebGL 2 through SwiftShader)"
  node tests/browser/page_test.mjs --web build/web --native build/native/pathtracer
  bash tools/site.sh >/dev/null
  phase "app_test"
  node tests/browser/app_test.mjs --web build/web
  phase "load_test"
  node tests/browser/load_test.mjs --web build/web --site build/site
  phase "error_test"
  node tests/browser/error_test.mjs --web build/web
  phase "gltf_page_test"
  node tests/browser/gltf_page_test.mjs --web build/web --native build/native/pathtracer
  phase "phone_test"
  node tests/browser/phone_test.mjs --web build/web
  phase "endurance_test"
  # Hours of use, shortened (every scene, then 3 rounds of loads, a context loss, edits and
  # reloads); --scale 1 is the full run, by hand (docs/reliability.md "Hours of use").
  node tests/browser/endurance_test.mjs --web build/web --native build/native/pathtracer --scale 0.2
fi
echo "== all tests passed in $(( $(date +%s) - start )) s"
