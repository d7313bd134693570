#!/usr/bin/env bash
# The peer benchmark (README "The peer benchmark"): installs the pinned npm packages
# (npm ci from package-lock.json; no browser is downloaded: Debian's /usr/bin/chromium is
# used) and runs bench.mjs with the arguments given, e.g.
#   bash tools/peers/run.sh                                   # 3 cycles, windows 30 and 120 s
#   bash tools/peers/run.sh reference --tracer ours --native --seconds 600
#   bash tools/peers/run.sh reference --tracer three-gpu-pt --seconds 3600
#   bash tools/peers/run.sh run --cycles 2 --windows 10       # a quick check that it works
# Our page must be built first: bash tools/site.sh (build/site), or cmake --build --preset web.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
export PUPPETEER_SKIP_DOWNLOAD=1 PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1
if [[ ! -f node_modules/.package-lock.json ]] || ! cmp -s package-lock.json node_modules/.peers-lock; then
  npm ci --no-audit --no-fund
  cp package-lock.json node_modules/.peers-lock
fi
[[ -x /usr/bin/chromium ]] || { echo "peers: needs Debian's chromium (apt-get install chromium)" >&2; exit 1; }
exec node bench.mjs "$@"
