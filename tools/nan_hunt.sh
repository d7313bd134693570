#!/usr/bin/env bash
# The NaN hunt (issue 15): renders every shipped scene and N generated ones
# (tools/gen_scenes.py) with the CLI, with each kernel, and logs the non-finite samples
# that `pathtracer render` counts (it exits 3 when there are any). Needs bash and python3.
#
#   bash tools/nan_hunt.sh BIN OUTDIR [options]
#     BIN                  the pathtracer binary (e.g. build/native/pathtracer)
#     OUTDIR               where the generated scenes and the log go (created)
#     --size WxH           image size (default 1920x1080)
#     --seconds S          render time per scene and kernel (default 8; 0: --spp decides)
#     --spp N              sample cap per scene and kernel (default 1000000: time decides)
#     --generated N        how many generated scenes (default 200)
#     --first-seed K       their seeds are K .. K+N-1 (default 1)
#     --seeds LIST         instead, these seeds (gen_scenes.py's form: 3,14,20-25)
#     --kernels "A B"      kernels to run (default "compute fragment")
#     --no-shipped         only the generated scenes
#     --shipped-part K/N   of the shipped scenes (sorted), only the K-th of every N (1 <= K <= N),
#                          so that N jobs side by side share them
#     --launcher CMD       run each render through CMD (the sanitizer build's tools/lsan_retry.sh)
#
# Writes OUTDIR/nan_hunt.log: one line per render (scene, kernel, exit status, spp, samples
# = spp x pixels, non-finite samples), then the totals and the seed list; each render's
# full output in OUTDIR/out/. Exit 0 when every render loaded and had no non-finite
# sample, 3 when any had some, 1 when a scene did not load or the binary failed.
# On the H200, the issue's budget (>= 1e10 samples, zero non-finite):
#   bash tools/nan_hunt.sh build/native/pathtracer /tmp/hunt --size 1920x1080 --seconds 8
# renders 14 shipped + 200 generated scenes x 2 kernels x 8 s (about an hour).
set -uo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${1:?usage: nan_hunt.sh BIN OUTDIR [options]}"
out="${2:?usage: nan_hunt.sh BIN OUTDIR [options]}"
shift 2
size=1920x1080 seconds=8 spp=1000000 generated=200 first=1 kernels="compute fragment" shipped=1 seeds="" launcher="" part=1/1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --size) size="$2"; shift ;;
    --seconds) seconds="$2"; shift ;;
    --spp) spp="$2"; shift ;;
    --generated) generated="$2"; shift ;;
    --first-seed) first="$2"; shift ;;
    --seeds) seeds="$2"; shift ;;
    --kernels) kernels="$2"; shift ;;
    --no-shipped) shipped=0 ;;
    --shipped-part) part="$2"; shift ;;
    --launcher) launcher="$2"; shift ;;
    *) echo "nan_hunt.sh: unknown option $1" >&2; exit 1 ;;
  esac
  shift
done
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"
mkdir -p "$out/out" "$out/scenes"
log="$out/nan_hunt.log"
last=$((first + generated - 1))
[[ -z "$seeds" && $generated -gt 0 ]] && seeds="$first-$last"
scenes=()
if [[ $shipped == 1 ]]; then
  [[ $part =~ ^([0-9]+)/([0-9]+)$ ]] && ((BASH_REMATCH[1] >= 1 && BASH_REMATCH[1] <= BASH_REMATCH[2])) ||
    { echo "nan_hunt.sh: --shipped-part wants K/N with 1 <= K <= N, not $part" >&2; exit 1; }
  k=${BASH_REMATCH[1]} n=${BASH_REMATCH[2]} i=0
  while IFS= read -r s; do
    (( i++ % n == k - 1 )) && scenes+=("$repo/$s")
  done < <(cd "$repo" && find scenes -name '*.xml' | sort)
fi
if [[ -n "$seeds" ]]; then
  while IFS= read -r s; do scenes+=("$s"); done < <(python3 "$repo/tools/gen_scenes.py" "$out/scenes" --seeds "$seeds" --repo "$repo") || exit 1
fi
{
  echo "# nan_hunt.sh $(date -u +%FT%TZ): $bin, $size, $seconds s and at most $spp spp per render, kernels: $kernels"
  echo "# generated seeds: ${seeds:-none} (python3 tools/gen_scenes.py DIR --seeds ${seeds:-none})"
  echo "# scene	kernel	status	spp	samples	non-finite"
} >"$log"
for s in "${scenes[@]}"; do
  name="${s#"$repo/"}"
  name="${name#"$out/"}"
  for k in $kernels; do
    o="$out/out/$(echo "$name" | tr '/' '-')-$k.txt"
    time_args=()
    [[ "$seconds" != 0 ]] && time_args=(--seconds "$seconds")
    (cd "$repo" && $launcher "$bin" render "$s" --size "$size" ${time_args[@]+"${time_args[@]}"} --spp "$spp" --kernel "$k" --out "$out/last.png") >"$o" 2>&1
    rc=$?
    python3 - "$o" "$name" "$k" "$rc" "$size" >>"$log" <<'EOF'
import re, sys
path, name, kernel, rc, size = sys.argv[1:]
text = open(path, errors="replace").read()
w, h = (int(x) for x in size.split("x"))
m = re.search(r"rendered (\d+) spp", text)
spp = int(m.group(1)) if m else 0
m = re.search(r"non-finite samples: (\d+)", text)
bad = m.group(1) if m else "-"
print("%s\t%s\t%s\t%d\t%d\t%s" % (name, kernel, rc, spp, spp * w * h, bad))
EOF
    echo "$(tail -n 1 "$log")"
  done
done
python3 - "$log" <<'EOF'
import os, sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if not l.startswith("#")]
samples = sum(int(r[4]) for r in rows)
bad = sum(int(r[5]) for r in rows if r[5] != "-")
failed = [r for r in rows if r[2] not in ("0", "3")]
with_bad = [r for r in rows if r[5] not in ("-", "0")]
lines = ["# renders: %d; samples: %d (%.3g); non-finite samples: %d, in %d renders; renders that failed: %d"
         % (len(rows), samples, samples, bad, len(with_bad), len(failed))]
for r in with_bad:
    lines.append("# non-finite: %s (%s kernel): %s of %s samples" % (r[0], r[1], r[5], r[4]))
for r in failed:
    lines.append("# failed: %s (%s kernel): exit %s" % (r[0], r[1], r[2]))
    # The render's own words (a sanitizer's report, a GL error), so that a failure in CI can
    # be read from the log alone.
    out = os.path.join(os.path.dirname(sys.argv[1]), "out", "%s-%s.txt" % (r[0].replace("/", "-"), r[1]))
    if os.path.exists(out):
        lines += ["#   " + l for l in open(out, errors="replace").read().splitlines()[-40:]]
open(sys.argv[1], "a").write("\n".join(lines) + "\n")
print("\n".join(lines))
sys.exit(1 if failed else (3 if bad else 0))
EOF
