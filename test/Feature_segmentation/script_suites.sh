#!/usr/bin/env bash
# ctest runs the Boost.Test executables one suite at a time (--run_test=SUITE), so a
# test case written outside every suite would never run. Fails if the listing of an
# executable (--list_content) shows a test case at its top level: a top-level entry not
# followed by an indented one is a case, not a suite.
# Run by ctest with FS_BINARY_DIR (top build folder) set.
set -uo pipefail
: "${FS_BINARY_DIR:?FS_BINARY_DIR must be set (the top build folder)}"
status=0
checked=0
for exe in "$FS_BINARY_DIR/test/Feature_segmentation/test_feature_segmentation" \
           "$FS_BINARY_DIR/benchmark/Feature_segmentation/test_evaluation"; do
  [ -x "$exe" ] || continue
  checked=$((checked + 1))
  if ! listing="$("$exe" --list_content 2>&1)"; then
    echo "script_suites: $exe --list_content failed" >&2
    status=1
    continue
  fi
  outside="$(printf '%s\n' "$listing" | awk '
    prev != "" && $0 !~ /^ / { print prev }
    { prev = ($0 ~ /^[^ ]/) ? $0 : "" }
    END { if(prev != "") print prev }')"
  if [ -n "$outside" ]; then
    echo "script_suites: test cases outside every suite in $(basename "$exe"), never run by ctest:" >&2
    printf '  %s\n' $outside >&2
    status=1
  else
    echo "ok   every test case of $(basename "$exe") is in a suite"
  fi
done
if [ "$checked" = 0 ]; then
  echo "script_suites: no test executable built under $FS_BINARY_DIR" >&2
  exit 1
fi
exit $status
