#!/usr/bin/env bash
# What motion blur costs (issue 15; docs/benchmarks.md, "Motion blur on every shape"):
# each scene still, then the same scene with one object moving over a shutter of 1
# (a static scene compiles no motion code: Features::motion), rendered for SECONDS each,
# REPEAT times in turn (ABAB..., so drift hits every variant alike):
#   box:     scenes/reference/scene2.xml / its emissive box (the light) moving 20 units in x
#   mesh:    scenes/bench/million.xml (1.3 M triangles) / the mesh moving 0.2 in x
#            (every triangle test then fetches its shape's velocity) / a small sphere
#            far away moving instead (the motion code compiled in, the mesh still)
# Here, on llvmpipe:   bash tools/bench_motion.sh 192x128 10 2
# On the H200 (run with build/native/pathtracer and .gl/ carried, as bench_device.sh):
#   for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig;
#   export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json;
#   bash tools/bench_motion.sh 1920x1080 5 3 | tee $OUT/log-motion.txt
# VARIANTS="mesh-still mesh-moving" picks some. Prints one line per render (spp/s, Mrays/s, BVH nodes) and a summary per variant.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
size="${1:-192x128}"
secs="${2:-10}"
repeat="${3:-2}"
bin="${PT_BIN:-build/native/pathtracer}"
w="$(mktemp -d)"
trap 'rm -rf "$w"' EXIT
shutter() { sed 's#<Camera \([^/]*\)/>#<Camera \1 shutter="1"/>#'; }
cp scenes/reference/scene2.xml "$w/box-still.xml"
# The first <Box> of scene2 is its emitter.
shutter < scenes/reference/scene2.xml | awk '!done && /<Box / { sub(/<Box /, "<Box velocity=\"20 0 0\" "); done = 1 } { print }' > "$w/box-moving.xml"
cp scenes/bench/million.xml "$w/mesh-still.xml"
shutter < scenes/bench/million.xml | sed 's#<Mesh #<Mesh velocity="0.2 0 0" #' > "$w/mesh-moving.xml"
shutter < scenes/bench/million.xml |
  sed 's#</Objects>#<Sphere center="30 0 -30" radius="0.1" velocity="0.1 0 0"><Diffuse/></Sphere></Objects>#' > "$w/mesh-still-motion-code.xml"
grep -q 'velocity="20 0 0"' "$w/box-moving.xml" && grep -q 'shutter="1"' "$w/box-moving.xml"
grep -q 'velocity="0.2 0 0"' "$w/mesh-moving.xml" && grep -q 'shutter="1"' "$w/mesh-moving.xml"
read -r -a variants <<< "${VARIANTS:-box-still box-moving mesh-still mesh-moving mesh-still-motion-code}"
"$bin" render "$w/box-still.xml" --size 64x64 --spp 1 --out "$w/warm.pfm" | grep '^GL:'
for ((r = 1; r <= repeat; ++r)); do
  for v in "${variants[@]}"; do
    out="$("$bin" render "$w/$v.xml" --size "$size" --spp 16777216 --seconds "$secs" --out "$w/$v.pfm")"
    sps="$(echo "$out" | sed -n 's/.*: \([0-9.]*\) spp\/s.*/\1/p')"
    mrays="$(echo "$out" | sed -n 's/.*, \([0-9.]*\) Mrays\/s.*/\1/p')"
    nodes="$(echo "$out" | sed -n 's/^BVH: .*primitives, \([0-9]*\) nodes.*/\1/p')"
    echo "$v run $r: $sps spp/s, $mrays Mrays/s, $nodes BVH nodes ($size, $secs s)"
    echo "$v $sps" >> "$w/all.txt"
  done
done
echo "mean spp/s over $repeat runs, spread (max - min) / mean:"
awk '{ s[$1] += $2; n[$1]++; if (!($1 in lo) || $2 < lo[$1]) lo[$1] = $2; if ($2 > hi[$1]) hi[$1] = $2 }
     END { for (v in s) printf "  %-24s %10.2f  %5.1f%%\n", v, s[v] / n[v], 100 * (hi[v] - lo[v]) / (s[v] / n[v]) }' "$w/all.txt" | sort
