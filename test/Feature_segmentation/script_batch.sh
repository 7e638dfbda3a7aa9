#!/usr/bin/env bash
# Tests `feature_segmentation batch`: a folder (searched recursively), a list file and a
# missing path as inputs, one output folder per mesh (names made unique), a table with a
# row per mesh in input order whose patch counts and files equal those of one-mesh runs,
# a bad mesh recorded without stopping the batch (exit status 1), resumption (complete
# outputs skipped; --force redoes them), the same table at 1 and 2 jobs, and the usage
# errors of the subcommand.
# Run by ctest with FS_BINARY_DIR (top build folder) and FS_MESH_DIR set.
set -uo pipefail

: "${FS_BINARY_DIR:?FS_BINARY_DIR must be set (the top build folder)}"
: "${FS_MESH_DIR:?FS_MESH_DIR must be set (the folder holding fandisk.off)}"
program="$FS_BINARY_DIR/demo/Feature_segmentation/feature_segmentation"
[ -x "$program" ] || { echo "script_batch: the program is not built: $program" >&2; exit 1; }

passed=0
failed=0
check() { # check DESCRIPTION COMMAND...
  local what="$1"; shift
  if "$@"; then passed=$((passed + 1)); echo "ok   $what"; else failed=$((failed + 1)); echo "FAIL $what" >&2; fi
}
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# inputs: a folder with two meshes and a bad one (in a subfolder), and a list naming
# fandisk again (from another folder: same name) and a file that does not exist
mkdir -p "$work/in/parts" "$work/other"
cp "$FS_MESH_DIR/rotor.off" "$FS_MESH_DIR/sphere.off" "$work/in/"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' > "$work/in/parts/broken.off"
cp "$FS_MESH_DIR/fandisk.off" "$work/other/fandisk.off"
cp "$FS_MESH_DIR/fandisk.off" "$work/in/parts/fandisk.off"
printf '# a list\nfandisk.off\n\nmissing.off  # not there\n' > "$work/other/list.txt"

"$program" batch "$work/in" "$work/other/list.txt" --output-dir "$work/out" --jobs 2 --quiet \
  > "$work/batch.out" 2> "$work/batch.err"
rc=$?
check "a batch with a bad mesh exits with status 1 (got $rc)" [ "$rc" -eq 1 ]
csv="$work/out/batch_summary.csv"
cut -d, -f1-5,7,8 "$csv" > "$work/table_before"
check "the table exists, CSV and JSON lines" [ -f "$csv" -a -f "$work/out/batch_summary.jsonl" ]
check "the table has a header and 6 rows" [ "$(wc -l < "$csv")" -eq 7 ]
check "6 JSON lines" [ "$(wc -l < "$work/out/batch_summary.jsonl")" -eq 6 ]
# rows in input order: the folder's meshes sorted (parts/broken, parts/fandisk, rotor,
# sphere), then the list's (fandisk, missing)
order="$(tail -n +2 "$csv" | cut -d, -f1 | sed "s|$work/||" | tr '\n' ' ')"
check "rows in input order ($order)" \
  [ "$order" = "in/parts/broken.off in/parts/fandisk.off in/rotor.off in/sphere.off other/fandisk.off other/missing.off " ]
field() { # field ROW COLUMN: a field of the CSV (rows from 1)
  tail -n +2 "$csv" | sed -n "$1p" | cut -d, -f"$2"
}
check "the bad mesh failed, with its reason ($(field 1 8))" [ "$(field 1 7)" = failed -a -n "$(field 1 8)" ]
check "the missing file failed: no such file" bash -c "tail -n +2 '$csv' | sed -n 6p | grep -q 'failed,.*no such file'"
check "four meshes done" [ "$(tail -n +2 "$csv" | cut -d, -f7 | grep -c '^done$')" -eq 4 ]
check "the two fandisks get two folders (fandisk, fandisk_2)" \
  [ "$(field 2 2)" = "$work/out/fandisk" -a "$(field 5 2)" = "$work/out/fandisk_2" ]
# fandisk's figures at the defaults: data/fandisk.json
fandisk_ref() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' \
                  "$(dirname "${BASH_SOURCE[0]}")/data/fandisk.json" "$1"; }
fandisk_faces="$(fandisk_ref faces)"
fandisk_patches="$(fandisk_ref patches)"
check "fandisk: $fandisk_faces faces and $fandisk_patches patches, as the program gives" \
  [ "$(field 2 3)" = "$fandisk_faces" -a "$(field 2 4)" = "$fandisk_patches" ]

# the same as one-mesh runs
"$program" "$FS_MESH_DIR/rotor.off" --output-dir "$work/single_rotor" --quiet
check "rotor: the batch's face_patches.txt equals the program's" \
  cmp -s "$work/out/rotor/face_patches.txt" "$work/single_rotor/face_patches.txt"
single_patches="$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["segmentation"]["patches"])' "$work/single_rotor/summary.json")"
check "rotor: the table's patches equal the program's ($single_patches)" [ "$(field 3 4)" = "$single_patches" ]

# resumption: complete outputs skipped, the failures tried again
"$program" batch "$work/in" "$work/other/list.txt" --output-dir "$work/out" --quiet 2> "$work/again.err"
rc=$?
check "the rerun still exits with 1 (got $rc)" [ "$rc" -eq 1 ]
check "the rerun skips the 4 complete meshes" [ "$(tail -n +2 "$csv" | cut -d, -f7 | grep -c '^skipped$')" -eq 4 ]
check "the rerun keeps their figures" [ "$(field 2 4)" = "$fandisk_patches" -a "$(field 3 4)" = "$single_patches" ]
# a mesh whose outputs were left incomplete (no summary.json) is done again
rm "$work/out/sphere/summary.json"
"$program" batch "$work/in" "$work/other/list.txt" --output-dir "$work/out" --quiet 2> /dev/null
check "an incomplete mesh is done again" [ "$(field 4 7)" = done ]

# --force at 1 job: the same table as the first run at 2 jobs, bar the seconds
"$program" batch "$work/in" "$work/other/list.txt" --output-dir "$work/out" --force --jobs 1 --quiet 2> /dev/null
check "--force redoes every mesh" [ "$(tail -n +2 "$csv" | cut -d, -f7 | grep -c '^done$')" -eq 4 ]
cut -d, -f1-5,7,8 "$csv" > "$work/table_after"
check "1 job and 2 jobs give the same table" cmp -s "$work/table_before" "$work/table_after"

# progress with a remaining-time estimate (without --quiet)
"$program" batch "$work/in/rotor.off" "$work/in/sphere.off" --output-dir "$work/progress" --force 2> "$work/progress.err"
check "progress lines with a remaining-time estimate" grep -q 'progress: \[1/2\] .*rotor.off: [0-9]* patches; about [0-9]* s left' "$work/progress.err"

# usage errors: status 2 and one line
usage() { # usage DESCRIPTION PATTERN ARGS...
  local what="$1" pattern="$2"; shift 2
  "$program" "$@" > /dev/null 2> "$work/usage.err"
  local rc=$? ok=1
  [ "$rc" -eq 2 ] && [ "$(wc -l < "$work/usage.err")" -eq 1 ] && grep -qF -- "$pattern" "$work/usage.err" || ok=0
  check "$what: status 2 and '$pattern' (got $rc: $(cat "$work/usage.err"))" [ "$ok" -eq 1 ]
}
usage "batch without --output-dir" "--output-dir DIR is required" batch "$work/in"
usage "batch without inputs" "no input" batch --output-dir "$work/x"
usage "batch --jobs 0" "--jobs must be" batch "$work/in" --output-dir "$work/x" --jobs 0
usage "--jobs outside batch" "--jobs is an option of 'batch'" "$FS_MESH_DIR/fandisk.off" --jobs 2
usage "--force outside batch" "--force is an option of 'batch'" "$FS_MESH_DIR/fandisk.off" --force
usage "batch --edits" "--edits is an option of one mesh" batch "$work/in" --output-dir "$work/x" --edits e.txt

echo "script_batch: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
