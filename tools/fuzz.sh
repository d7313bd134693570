#!/usr/bin/env bash
# Builds the libFuzzer targets (preset fuzz: clang, ASan + UBSan) and runs each for a
# bounded time from its seed corpus (tests/fuzz/corpus/<name>/ plus the malformed files
# of its format, and the kept corpus tests/fuzz/kept/<name>.tar.gz). New inputs go to a
# scratch folder, so the repository is not changed.
#   bash tools/fuzz.sh                 every target, PT_FUZZ_SECONDS (default 30) each
#   PT_FUZZ_SECONDS=600 bash tools/fuzz.sh image     one target, longer
# A crash stops the script (exit 1) and leaves the input in build/fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds="${PT_FUZZ_SECONDS:-30}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(scene_xml mesh_json mesh_obj mesh_gltf image)
seeds_for() {  # extra seed folders: the malformed files of the target's formats
  case "$1" in
    scene_xml) echo tests/malformed/xml ;;
    mesh_json) echo tests/malformed/json ;;
    mesh_obj) echo tests/malformed/obj ;;
    mesh_gltf) echo tests/malformed/gltf ;;
    image) echo tests/malformed/hdr tests/malformed/png tests/malformed/pfm ;;
  esac
}
mkdir -p build/fuzz/artifacts
# One target's run; its summary goes to build/fuzz/$t.out, its exit status to $t.status.
run_target() {
  local t=$1 work="build/fuzz/corpus-$1" log="build/fuzz/$1.log" status=0 dict=()
  mkdir -p "$work"
  # The kept corpus (what the long runs found, minimised: tools/fuzz_device.sh) seeds it.
  [[ -f "tests/fuzz/kept/$t.tar.gz" ]] && tar xzf "tests/fuzz/kept/$t.tar.gz" -C "$work"
  [[ -f "tests/fuzz/$t.dict" ]] && dict=(-dict="tests/fuzz/$t.dict")
  echo "== fuzz $t for ${seconds} s"
  # -timeout: one input taking over 10 s is a finding (a hang); -rss_limit_mb: so is 2 GB.
  # Crashes, leaks, UBSan reports and uncaught exceptions all end the run non-zero.
  # shellcheck disable=SC2046
  build/fuzz/fuzz_"$t" "${dict[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="build/fuzz/artifacts/$t-" \
    "$work" "tests/fuzz/corpus/$t" $(seeds_for "$t") >"$log" 2>&1 || status=$?
  grep -E "^(stat::number_of_executed_units|stat::average_exec_per_sec|stat::new_units_added|stat::peak_rss_mb|SUMMARY)" "$log" || true
  if [[ $status -ne 0 ]]; then
    grep -E -A30 "==[0-9]+==ERROR|runtime error|uncaught|deadly signal|Timeout" "$log" | head -60 || tail -40 "$log"
    echo "fuzz $t: FINDING (exit $status; input in build/fuzz/artifacts/, log $log)"
  fi
  return "$status"
}
# The targets run side by side, PT_FUZZ_JOBS at a time (default: one per core); each is
# one process, so the time per target is the same and the wall time is shared.
jobs_max="${PT_FUZZ_JOBS:-$(nproc)}"
for t in "${targets[@]}"; do
  while (( $(jobs -rp | wc -l) >= jobs_max )); do wait -n || true; done
  ( run_target "$t" >"build/fuzz/$t.out" 2>&1; echo $? >"build/fuzz/$t.status" ) &
done
wait
failed=0
for t in "${targets[@]}"; do
  cat "build/fuzz/$t.out"
  [[ "$(cat "build/fuzz/$t.status")" == 0 ]] || failed=1
done
[[ $failed == 0 ]] || exit 1
echo "== fuzz: no findings"
