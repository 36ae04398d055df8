#!/bin/bash
# Run every fuzz target of a build for a fixed time, one after another, at low priority, and
# print the README table (target, minutes, executions, crashes, corpus). Seeds are read from
# tests/fuzz/corpus/<target>/ and never written; the growing corpus and any crash artifacts
# go to BUILD/fuzz-work/<target>/. REFLOC_FUZZ_NICE (default 19) is the nice level.
#   tests/fuzz/run_fuzz.sh BUILD_DIR SECONDS_PER_TARGET [TARGET...]
set -u
build=${1:?usage: run_fuzz.sh BUILD_DIR SECONDS [TARGET...]}
seconds=${2:?seconds per target}
shift 2
here=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for exe in "$build"/bin/*_fuzz; do targets+=("$(basename "$exe")"); done
fi
echo "| target | minutes | executions | exec/s | crashes | corpus files |"
echo "| --- | --- | --- | --- | --- | --- |"
for target in "${targets[@]}"; do
  case $target in
    json_config_fuzz | reflector_map_fuzz) max_len=16384 ;;
    *) max_len=4096 ;;
  esac
  work="$build/fuzz-work/$target"
  mkdir -p "$work/corpus" "$work/artifacts"
  log="$work/run.log"
  nice -n "${REFLOC_FUZZ_NICE:-19}" "$build/bin/$target" -max_total_time="$seconds" -max_len=$max_len -rss_limit_mb=512 \
    -malloc_limit_mb=512 -timeout=10 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
    "$work/corpus" "$here/corpus/$target" > "$log" 2>&1
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  crashes=$(find "$work/artifacts" -type f | wc -l)
  corpus=$(find "$work/corpus" -type f | wc -l)
  minutes=$(awk "BEGIN { printf \"%.1f\", $seconds / 60 }")
  echo "| $target | $minutes | ${executions:-?} | ${rate:-?} | $crashes | $corpus |"
done
