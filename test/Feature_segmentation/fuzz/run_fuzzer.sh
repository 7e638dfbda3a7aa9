#!/usr/bin/env bash
# run_fuzzer.sh FUZZER FOUND_DIR CORPUS_DIR SECONDS: fuzzes for SECONDS seconds, starting
# from CORPUS_DIR (read only) and keeping what it finds in FOUND_DIR; a crash leaves its
# input in FOUND_DIR.artifacts/ (crash-*, timeout-*, oom-*) and fails the test. Prints libFuzzer's final statistics.
set -u
fuzzer="$1" found="$2" corpus="$3" seconds="$4"
mkdir -p "$found" "$found.artifacts"
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
  -artifact_prefix="$found.artifacts/" \
  -print_final_stats=1 "$found" "$corpus" > "$found.log" 2>&1
status=$?
grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)|ERROR|SUMMARY' "$found.log"
exit "$status"
