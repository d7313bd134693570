#!/usr/bin/env bash
# Fuzzing volume on a many-core machine (the lent H200 host's 16 cores; no GPU used):
# runs each named libFuzzer target with W parallel workers for S seconds from its kept
# corpus (tests/fuzz/kept/<t>.tar.gz, tests/fuzz/corpus/<t>/, the malformed files of its
# format), sums the executions over the workers, then merges the kept corpus and what
# they found into a minimal corpus, $OUT/corpus-<t>.tar.gz: copy it over
# tests/fuzz/kept/<t>.tar.gz, so the corpus and the counts accumulate over runs
# (docs/reliability.md). A finding leaves its input in
# $OUT/artifacts-<t>.tar.gz and the script exits 1.
#   Built here first:  cmake --preset fuzz && cmake --build --preset fuzz
#   then copy build/fuzz/fuzz_* and libtinyxml2.so.9 into build/fuzzdev/ and carry it:
#   FUZZ_WORKERS=15 FUZZ_SECONDS=170 bash tools/fuzz_device.sh scene_xml mesh_obj mesh_gltf
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
workers="${FUZZ_WORKERS:-15}"
seconds="${FUZZ_SECONDS:-170}"
bin="${FUZZ_BIN:-build/fuzzdev}"
out="${OUT:-/tmp/fuzz-out}"
mkdir -p "$out"
export LD_LIBRARY_PATH="$PWD/$bin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
seeds_for() {
  case "$1" in
    scene_xml) echo tests/malformed/xml ;; mesh_json) echo tests/malformed/json ;;
    mesh_obj) echo tests/malformed/obj ;; mesh_gltf) echo tests/malformed/gltf ;;
    image) echo tests/malformed/hdr tests/malformed/png tests/malformed/pfm ;;
  esac
}
status=0
for t in "$@"; do
  work="/tmp/fuzz/$t"; logs="/tmp/fuzz/logs-$t"; art="/tmp/fuzz/art-$t"
  rm -rf "$work" "$logs" "$art"; mkdir -p "$work" "$logs" "$art"
  [[ -f "tests/fuzz/kept/$t.tar.gz" ]] && tar xzf "tests/fuzz/kept/$t.tar.gz" -C "$work"
  dict=(); [[ -f "tests/fuzz/$t.dict" ]] && dict=(-dict="$PWD/tests/fuzz/$t.dict")
  # shellcheck disable=SC2046
  seeds=("$PWD/tests/fuzz/corpus/$t" $(for s in $(seeds_for "$t"); do echo "$PWD/$s"; done))
  before=$(ls "$work" | wc -l)
  echo "== $t: $workers workers x $seconds s (kept corpus: $before files)"
  ( cd "$logs" && "$OLDPWD/$bin/fuzz_$t" "${dict[@]}" -jobs="$workers" -workers="$workers" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -print_final_stats=1 -artifact_prefix="$art/" "$work" "${seeds[@]}" >/dev/null 2>&1 )
  execs=$(cat "$logs"/fuzz-*.log | awk '/^stat::number_of_executed_units/ {s += $2} END {print s + 0}')
  cov=$(cat "$logs"/fuzz-*.log | grep -oE "cov: [0-9]+" | awk '{if ($2 > m) m = $2} END {print m + 0}')
  finds=$(ls "$art" | wc -l)
  echo "$t: executions $execs, max coverage (edges) $cov, findings $finds"
  grep -hE "==[0-9]+==ERROR|runtime error|uncaught|deadly signal|Timeout|Out-of-memory" "$logs"/fuzz-*.log | sort | uniq -c | head -20
  if [[ $finds -gt 0 ]]; then status=1; tar czf "$out/artifacts-$t.tar.gz" -C "$art" .; fi
  # The kept corpus grows by what this run found, minimised (libFuzzer's -merge=1).
  merged="/tmp/fuzz/merged-$t"; rm -rf "$merged"; mkdir -p "$merged"
  "$bin/fuzz_$t" -merge=1 -timeout=10 -rss_limit_mb=2048 -max_len=65536 "$merged" \
    "tests/fuzz/corpus/$t" "$work" >"$logs/merge.log" 2>&1
  echo "$t: merged corpus $(ls "$merged" | wc -l) files ($(du -sh "$merged" | cut -f1))"
  tar czf "$out/corpus-$t.tar.gz" -C "$merged" .
done
exit $status
