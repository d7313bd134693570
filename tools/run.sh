#!/usr/bin/env bash
# README command (1): install what is missing, build the web page, serve it locally.
#   bash tools/run.sh [PORT]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash tools/deps.sh web
export NODE_PATH=/usr/share/nodejs
cmake --preset web >/dev/null
cmake --build --preset web
exec node tools/serve.mjs build/web "${1:-8000}" --dev
