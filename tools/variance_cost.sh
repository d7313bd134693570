#!/usr/bin/env bash
# The camera pass's cost of what it accumulates besides the mean, A/B: renders one scene
# with each binary (and configuration) in turn, ROUNDS times interleaved so a busy machine
# slows each alike, and prints each one's spp/s: median, min and max.
#   PT_A=/path/to/old/pathtracer PT_B=build/native/pathtracer bash tools/variance_cost.sh
# Environment: PT_A (default /work/main/build/native/pathtracer), PT_B (default
# build/native/pathtracer), SCENE (scenes/reference/scene0.xml), SIZE (256x256), SPP (32),
# PASS (4: samples per draw), KERNEL (fragment), ROUNDS (5). Configurations: A, B, and B
# with --denoise (the first-hit auxiliaries written too; the denoiser runs once at the end,
# outside the timed render).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
a="${PT_A:-/work/main/build/native/pathtracer}"
b="${PT_B:-build/native/pathtracer}"
scene="${SCENE:-scenes/reference/scene0.xml}"
size="${SIZE:-256x256}"
spp="${SPP:-32}"
pass="${PASS:-4}"
kernel="${KERNEL:-fragment}"
rounds="${ROUNDS:-5}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
names=("A" "B" "B --denoise")
for ((r = 0; r < rounds; r++)); do
  for i in 0 1 2; do
    bin="$a"; extra=()
    if ((i > 0)); then bin="$b"; fi
    if ((i == 2)); then extra=(--denoise); fi
    "$bin" render "$scene" --kernel "$kernel" --size "$size" --spp "$spp" --spp-per-pass "$pass" "${extra[@]}" \
      --out "$out/x.pfm" | sed -n 's/.* s: \([0-9.]*\) spp\/s.*/\1/p' >>"$out/$i"
  done
done
echo "$scene at $size, $spp spp in passes of $pass, $kernel kernel, $rounds rounds; spp/s median (min..max):"
for i in 0 1 2; do
  sort -g "$out/$i" | awk -v n="${names[$i]}" '{v[NR]=$1} END {printf "  %-12s %8.2f  (%.2f..%.2f)\n", n, v[int((NR+1)/2)], v[1], v[NR]}'
done
echo "A = $a"
echo "B = $b"
