#!/usr/bin/env bash
# Where SwiftShader's time goes in the page (issue 17): runs tools/page_cost.mjs on WEBDIR
# and, during its page window, `perf record -a` (Debian's linux-perf; root); then groups
# the samples in SwiftShader's JIT code (the compiled shaders and blit routines, which
# have no symbols) by 64 KB region, adjacent regions merged into one routine, with how
# many bursts (runs of samples less than 20 ms apart) each had: the path tracer runs in
# long bursts, a per-present pass in ~10 short ones a second. One sample is 1/499 s of
# one core. A measurement a person runs, not a CI test.
#   bash tools/page_perf.sh build/web [page_cost.mjs options, e.g. --denoise off]
set -euo pipefail
web=${1:?web build folder}; shift
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=$(mktemp -d)
NODE_PATH=/usr/share/nodejs node tools/page_cost.mjs --web "$web" --cycles 1 --warmup 8 --seconds 25 --raw-rows 0 "$@" > "$out/page_cost.txt" 2>&1 &
runner=$!
sleep 16  # the page loads, renders its first sample and warms up; the window is then open
perf record -a -F 499 -o "$out/perf.data" -- sleep 18 > /dev/null 2>&1
perf script -i "$out/perf.data" -F time,ip,dso -G 2> /dev/null | grep swiftshader_jit |
  awk '{t = $1; sub(":", "", t); a = $2; print t, substr(a, 1, length(a) - 4)}' > "$out/jit.txt"
wait $runner
grep -E "^# page|^page" "$out/page_cost.txt"
python3 - "$out/jit.txt" <<'PY'
import collections, sys
rows = [l.split() for l in open(sys.argv[1])]
by_region = collections.defaultdict(list)
for t, r in rows:
    by_region[r].append(float(t))
routines, cur = [], []
for r in sorted(by_region, key=lambda r: int(r, 16)):
    if cur and int(r, 16) - int(cur[-1], 16) > 1:
        routines.append(cur)
        cur = []
    cur.append(r)
routines.append(cur)
span = max(float(t) for t, _ in rows) - min(float(t) for t, _ in rows)
print(f"{len(rows)} samples in SwiftShader's JIT code over {span:.1f} s")
for g in sorted(routines, key=lambda g: -sum(len(by_region[r]) for r in g)):
    ts = sorted(sum((by_region[r] for r in g), []))
    bursts = 1 + sum(1 for a, b in zip(ts, ts[1:]) if b - a > 0.02)
    print(f"  {g[0]}..{g[-1]}: {len(ts)} samples ({100 * len(ts) / len(rows):.0f}%), {bursts / span:.1f} bursts/s of {len(ts) / bursts:.1f}")
PY
rm -rf "$out"
