#!/usr/bin/env bash
# Renders every shipped scene at 16 spp in one render mode and compares the linear images
# byte for byte with an earlier set: a refactoring that changes nothing for users leaves
# every file identical (issue 12, point 6).
#   bash tools/compare_renders.sh save DIR        render every scene into DIR
#   bash tools/compare_renders.sh compare DIR     render again and cmp each image with DIR
# Environment: PT_BIN (default build/native/pathtracer), MODE (default path), SIZE
# (default 128x96), SPP (default 16), KERNEL (compute or fragment; default: the binary's). Exit 1 when any image differs or is missing.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
what="${1:?save|compare}"
dir="${2:?DIR}"
bin="${PT_BIN:-build/native/pathtracer}"
mode="${MODE:-path}"
size="${SIZE:-128x96}"
spp="${SPP:-16}"
kernel=()
if [[ -n "${KERNEL:-}" ]]; then kernel=(--kernel "$KERNEL"); fi
out="$dir"
if [[ "$what" == compare ]]; then out="$(mktemp -d)"; trap 'rm -rf "$out"' EXIT; fi
mkdir -p "$out"
status=0
for s in $(find scenes -name '*.xml' | sort); do
  n="$(echo "${s#scenes/}" | sed 's#/#-#g; s#\.xml$##')-$mode.pfm"
  # One pass of all the samples: the default adapts the pass size to time, and the running
  # mean rounds differently for other splits.
  "$bin" render "$s" --mode "$mode" --spp "$spp" --spp-per-pass "$spp" --size "$size" "${kernel[@]}" --out "$out/$n" >/dev/null
  if [[ "$what" == compare ]]; then
    if [[ ! -f "$dir/$n" ]]; then
      echo "missing  $n (not in $dir)"
      status=1
    elif cmp -s "$dir/$n" "$out/$n"; then
      echo "same     $n"
    else
      echo "DIFFERS  $n"
      status=1
    fi
  else
    echo "saved    $n"
  fi
done
exit $status
