#!/usr/bin/env bash
# The NaN hunt on the lent GPU machine in one call of under 10 minutes: several
# tools/nan_hunt.sh runs side by side (the GPU renders one at a time; the shader compiles,
# on the CPU, overlap), each over its own seed range, 1 s per scene and kernel at 1080p.
#   bash tools/nan_hunt_device.sh BIN FIRST_SEED COUNT_PER_JOB JOBS [--shipped]
# (HUNT_LIMIT: seconds before each job is stopped, default 480; HUNT_SECONDS per render)
# Carry BIN (e.g. build/bench/pt-hunt) and .gl/; the logs go to $OUT/hunt-<first seed>/.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bin="${1:?BIN}" first="${2:?FIRST_SEED}" per="${3:?COUNT_PER_JOB}" jobs="${4:?JOBS}" shipped="${5:-}"
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[[ -f $nv ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nv
out="${OUT:-out}"
pids=()
for ((j = 0; j < jobs; ++j)); do
  s=$((first + j * per))
  flags=(--size 1920x1080 --seconds "${HUNT_SECONDS:-1}" --first-seed "$s" --generated "$per")
  [[ $j -gt 0 || $shipped != --shipped ]] && flags+=(--no-shipped)
  timeout "${HUNT_LIMIT:-480}" bash tools/nan_hunt.sh "$bin" "/tmp/hunt-$s" "${flags[@]}" > "/tmp/hunt-$s.stdout" 2>&1 &
  pids+=($!)
done
for p in "${pids[@]}"; do wait "$p"; done
for ((j = 0; j < jobs; ++j)); do
  s=$((first + j * per))
  mkdir -p "$out/hunt-$s"
  cp "/tmp/hunt-$s/nan_hunt.log" "$out/hunt-$s/" 2>/dev/null
  echo "== seeds from $s"
  tail -n 6 "/tmp/hunt-$s/nan_hunt.log"
  grep -E "non-finite [1-9]|rc [^03]" "/tmp/hunt-$s/nan_hunt.log" | head -20
done
