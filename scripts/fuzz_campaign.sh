#!/usr/bin/env bash
# A fuzzing campaign: runs libFuzzer targets of BUILD_DIR (configured with
# -DFEATURE_SEGMENTATION_BUILD_FUZZERS=ON, see scripts/run_tests.sh) for MINUTES each,
# JOBS at a time, from the seed corpus and what earlier campaigns found (kept in
# OUT_DIR/<target>/), and prints a table: executions, coverage (edges), features,
# corpus size, peak memory and the crashes, timeouts and out-of-memory inputs found
# (saved in OUT_DIR/<target>.artifacts/).
# Usage: scripts/fuzz_campaign.sh BUILD_DIR OUT_DIR MINUTES [JOBS] [TARGET...]
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$1" out="$2" minutes="$3" jobs="${4:-2}"
shift 3; [ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(fuzz_read_off fuzz_read_obj fuzz_read_ply fuzz_read_stl)
bin="$build/test/Feature_segmentation/fuzz"
corpus="$here/test/Feature_segmentation/fuzz/corpus"
mkdir -p "$out"

run_one() {
  local t="$1"
  mkdir -p "$out/$t" "$out/$t.artifacts"
  "$bin/$t" -max_total_time=$((minutes * 60)) -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    -artifact_prefix="$out/$t.artifacts/" -print_final_stats=1 \
    "$out/$t" "$corpus/$t" > "$out/$t.log" 2>&1
}

running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
done
wait

echo "| target | minutes | executions | exec/s | coverage (edges) | features | corpus | peak MB | crashes | timeouts | oom |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for t in "${targets[@]}"; do
  log="$out/$t.log"
  stat() { sed -n "s/^stat::$1: *//p" "$log" | tail -1; }
  last="$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE)' "$log" | tail -1)"
  cov="$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")"
  ft="$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")"
  corp="$(sed -n 's/.* corp: \([0-9]*\)\/.*/\1/p' <<<"$last")"
  count() { find "$out/$t.artifacts" -name "$1-*" | wc -l; }
  echo "| $t | $minutes | $(stat number_of_executed_units) | $(stat average_exec_per_sec) | $cov | $ft | $corp | $(stat peak_rss_mb) | $(count crash) | $(count timeout) | $(count oom) |"
done
