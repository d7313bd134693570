#!/usr/bin/env bash
# The NaN hunt on the lent GPU machine in one call of under 10 minutes: several
# tools/nan_hunt.sh runs side by side (the GPU renders one at a time; the shader compiles,
# on the CPU, overlap), one per JOB, 1 s per scene and kernel at 1080p.
#   bash tools/nan_hunt_device.sh BIN JOB...
# A JOB is seeds=LIST (generated scenes, gen_scenes.py's form: 1-10,14) or shipped=K/N (the
# K-th of every N shipped scenes: give the shipped scenes jobs of their own, since some
# take 20 s a render and would starve a job's seeds).
#   bash tools/nan_hunt_device.sh build/bench/pt-hunt shipped=1/3 shipped=2/3 shipped=3/3 seeds=1-12 seeds=13-24
# (HUNT_LIMIT: seconds before each job is stopped, default 480; HUNT_SECONDS per render)
# Carry BIN (e.g. build/bench/pt-hunt) and .gl/; the logs go to $OUT/hunt-<job>/.
# (Until 2026-12-04 the form was BIN FIRST_SEED COUNT_PER_JOB JOBS [--shipped]: job j took
# seeds FIRST + j * COUNT .. and the first job the shipped scenes too.)
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bin="${1:?BIN}"
shift
[[ $# -gt 0 ]] || { echo "nan_hunt_device.sh: no JOB (seeds=LIST or shipped=K/N)" >&2; exit 1; }
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[[ -f $nv ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nv
out="${OUT:-out}"
names=() pids=()
for job in "$@"; do
  flags=(--size 1920x1080 --seconds "${HUNT_SECONDS:-1}")
  case "$job" in
    seeds=*) flags+=(--seeds "${job#seeds=}" --no-shipped) ;;
    shipped=*) flags+=(--generated 0 --shipped-part "${job#shipped=}") ;;
    *) echo "nan_hunt_device.sh: a JOB is seeds=LIST or shipped=K/N, not $job" >&2; exit 1 ;;
  esac
  name="$(echo "$job" | sed 's/[=/,]/_/g')"
  timeout "${HUNT_LIMIT:-480}" bash tools/nan_hunt.sh "$bin" "/tmp/hunt-$name" "${flags[@]}" > "/tmp/hunt-$name.stdout" 2>&1 &
  names+=("$name") pids+=($!)
done
status=() rc=0
for p in "${pids[@]}"; do wait "$p"; status+=($?); done
for i in "${!names[@]}"; do
  name=${names[$i]} log="/tmp/hunt-${names[$i]}/nan_hunt.log"
  case ${status[$i]} in
    0) echo "== $name" ;;
    124) echo "== $name: stopped at HUNT_LIMIT (the scenes below the last line were not rendered)" ;;
    *) echo "== $name: exit ${status[$i]}"; rc=1 ;;
  esac
  [[ -f $log ]] || { echo "no log: the job did not start"; cat "/tmp/hunt-$name.stdout"; rc=1; continue; }
  mkdir -p "$out/hunt-$name"
  cp "$log" "$out/hunt-$name/"
  tail -n 6 "$log"
  grep -E "^# (non-finite|failed):" "$log" | head -20
done
exit $rc
