#!/usr/bin/env bash
# Tests the inputs of the command-line program `feature_segmentation`: a quad mesh that
# must be triangulated with a notice, patch files that follow the input file's order
# through the reader's repairs, binary STL and ASCII PLY, and every kind of bad input
# and bad option, each of which must end in one "error:" line on stderr and the
# documented exit status (1 for bad input, 2 for a bad command line), never a crash or a
# hang. The runs on fandisk and their outputs are in script_program.sh; the shared setup
# and checks in program_common.sh.
# Run by ctest with FS_BINARY_DIR (top build folder) and FS_MESH_DIR set.
set -uo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/program_common.sh"

# ---- a quad mesh: triangulated, with a notice -------------------------------------------
# An open box of five unit squares (no top): 8 vertices, 5 quads -> 10 triangles.
write_box_off "$work/box.off"
run quad "$work/box.off" --output-dir "$work/quad"
check "quad mesh: exit status 0 (stderr: $(tail -n 1 "$work/quad.err"))" [ "$rc" -eq 0 ]
check "quad mesh: notice about triangulation" grep -q '^notice: .*triangulated 5 faces' "$work/quad.err"
check "quad mesh: 10 triangles" [ "$(json_int "$work/quad/summary.json" mesh faces)" = 10 ]
check "quad mesh: 4 border edges" [ "$(json_int "$work/quad/summary.json" mesh border_edges)" = 4 ]
check "quad mesh: 8 lines in vertex_patches.txt" [ "$(wc -l < "$work/quad/vertex_patches.txt")" -eq 8 ]
check "quad mesh: 5 lines in face_patches.txt (one per quad)" [ "$(wc -l < "$work/quad/face_patches.txt")" -eq 5 ]
check "quad mesh: segmentation.ply has the 10 triangles" \
  ply_header_ok "$work/quad/segmentation.ply" 8 10

# ---- patch files in the file's order, through the repairs -------------------------------
# The box again, with a duplicate of point 2 (point 8, used by face 2 instead of 2), a
# point no face uses (point 9) and a duplicate of face 0 with the other orientation
# (face 5). The mesh has 8 vertices and 10 triangles; the patch files have the file's 10
# vertices and 6 faces. alpha 2 splits the box (measured: 2 patches).
{ echo OFF; echo '10 6 0'; sed -n 3,10p "$work/box.off"; printf '1 1 0\n5 5 5\n'
  sed -n 11,15p "$work/box.off" | sed '3s/.*/4 1 8 6 5/'; echo '4 1 2 3 0'; } > "$work/box_duplicates.off"
run duplicates "$work/box_duplicates.off" --output-dir "$work/duplicates" --alpha 2
check "duplicates: exit status 0 (stderr: $(tail -n 1 "$work/duplicates.err"))" [ "$rc" -eq 0 ]
check "duplicates: notice about the removed vertices" \
  grep -q '^notice: .*removed 2 duplicate or unused vertices' "$work/duplicates.err"
check "duplicates: notice about the removed face" \
  grep -q '^notice: .*removed 1 duplicate faces' "$work/duplicates.err"
check "duplicates: mesh of 8 vertices and 10 faces" \
  [ "$(json_int "$work/duplicates/summary.json" mesh vertices)" = 8 -a \
   "$(json_int "$work/duplicates/summary.json" mesh faces)" = 10 ]
vp="$work/duplicates/vertex_patches.txt"; fp="$work/duplicates/face_patches.txt"
line() { sed -n "$(($2 + 1))p" "$1"; }
dup_patches="$(json_int "$work/duplicates/summary.json" segmentation patches)"
check "duplicates: 10 lines in vertex_patches.txt" [ "$(wc -l < "$vp")" -eq 10 ]
check "duplicates: 6 lines in face_patches.txt" [ "$(wc -l < "$fp")" -eq 6 ]
check "duplicates: more than one patch (got ${dup_patches:-none})" [ "${dup_patches:-0}" -gt 1 ]
check "duplicates: point 8 has the patch of point 2" [ "$(line "$vp" 8)" = "$(line "$vp" 2)" ]
check "duplicates: the unused point 9 has patch -1" [ "$(line "$vp" 9)" = -1 ]
check "duplicates: face 5 has the patch of face 0" [ "$(line "$fp" 5)" = "$(line "$fp" 0)" ]
check "duplicates: vertex ids of points 0..8 cover [0, $dup_patches)" \
  ids_cover <(head -n 9 "$vp") "${dup_patches:-0}"
check "duplicates: face ids in [0, $dup_patches)" ids_in_range "$fp" "${dup_patches:-0}"

# A bow tie: two triangles sharing only point 0, which the reader splits in two. The two
# triangles are not connected, so they are two patches; point 0 has the patch of its copy
# in the first face that uses it (face 0, with points 1 and 2).
printf 'OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n' > "$work/bowtie.off"
run bowtie "$work/bowtie.off" --output-dir "$work/bowtie" --quiet
check "bow tie: exit status 0 (stderr: $(tail -n 1 "$work/bowtie.err"))" [ "$rc" -eq 0 ]
check "bow tie: 6 mesh vertices (point 0 split)" [ "$(json_int "$work/bowtie/summary.json" mesh vertices)" = 6 ]
check "bow tie: 2 patches" [ "$(json_int "$work/bowtie/summary.json" segmentation patches)" = 2 ]
check "bow tie: 5 lines in vertex_patches.txt, 2 in face_patches.txt" \
  [ "$(wc -l < "$work/bowtie/vertex_patches.txt")" -eq 5 -a "$(wc -l < "$work/bowtie/face_patches.txt")" -eq 2 ]
check "bow tie: point 0 in face 0's patch, points 3 and 4 in face 1's" \
  [ "$(paste -s -d ' ' "$work/bowtie/vertex_patches.txt") / $(paste -s -d ' ' "$work/bowtie/face_patches.txt")" = "0 0 0 1 1 / 0 1" ]

# ---- the other formats (fandisk as OBJ: script_program.sh) -------------------------------
# Binary STL, written byte by byte: 80-byte header, triangle count, then per triangle a
# normal, three points (little-endian floats) and 2 attribute bytes.
f0='\x00\x00\x00\x00'; f1='\x00\x00\x80\x3f'
stl_triangle() { printf "$f0$f0$f0$1$2$3"'\x00\x00'; }
{ head -c 80 /dev/zero; printf '\x04\x00\x00\x00'
  stl_triangle "$f0$f0$f0" "$f0$f1$f0" "$f1$f0$f0"
  stl_triangle "$f0$f0$f0" "$f0$f0$f1" "$f0$f1$f0"
  stl_triangle "$f0$f0$f0" "$f1$f0$f0" "$f0$f0$f1"
  stl_triangle "$f1$f0$f0" "$f0$f1$f0" "$f0$f0$f1"; } > "$work/tetrahedron.stl"
run stl "$work/tetrahedron.stl" --output-dir "$work/stl" --quiet
check "tetrahedron.stl: exit status 0 (stderr: $(tail -n 1 "$work/stl.err"))" [ "$rc" -eq 0 ]
check "tetrahedron.stl: 4 vertices (shared points merged)" \
  [ "$(json_int "$work/stl/summary.json" mesh vertices)" = 4 ]
check "tetrahedron.stl: closed (0 border edges)" \
  [ "$(json_int "$work/stl/summary.json" mesh border_edges)" = 0 ]

cat > "$work/tetrahedron.ply" <<'EOF'
ply
format ascii 1.0
element vertex 4
property double x
property double y
property double z
element face 4
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
EOF
run ply "$work/tetrahedron.ply" --output-dir "$work/ply" --quiet
check "tetrahedron.ply: exit status 0 (stderr: $(tail -n 1 "$work/ply.err"))" [ "$rc" -eq 0 ]
check "tetrahedron.ply: 4 faces" [ "$(json_int "$work/ply/summary.json" mesh faces)" = 4 ]

# ---- bad input ----------------------------------------------------------------------------
bad="$work/bad"
mkdir -p "$bad"
# Edit scripts with one mistake each, after valid lines where the line number matters.
printf 'alpha 0.8\nfrob 1\n' > "$bad/verb.edits"
printf '# a comment\n\nalpha 1 2\n' > "$bad/arity.edits"
printf 'refine ball 0 0 0 0.3\n' > "$bad/ball_arity.edits"
printf 'refine ball 0 0 zero 0.3 0.5\n' > "$bad/number.edits"
printf 'alpha 0.8\nalpha inf\n' > "$bad/infinite.edits"
printf 'scale ball 0 0 0 0.1 nan\n' > "$bad/nan.edits"
printf 'merge ball 0 0 0 0\n' > "$bad/radius.edits"
# with no memory for the history (--undo-memory 0), the library keeps only the state
# before the last edit: the second undo (line 4) cannot take back line 1 (65 edits and
# 65 undos within the default 256 MiB undo every edit: script_program.sh)
printf 'alpha 0.7\nalpha 0.6\nundo\nundo\n' > "$bad/undo_memory.edits"
printf 'merge ball 0 0 0 -1\n' > "$bad/radius_negative.edits"
printf 'merge faces 0 12946\n' > "$bad/face_range.edits"
printf 'merge faces 0 -1\n' > "$bad/face_negative.edits"
printf 'merge sphere 0 0 0 1\n' > "$bad/region.edits"
printf 'scale faces 1 2 -1.5\n' > "$bad/factor.edits"
printf 'sketch 0 0 0 1 1\n' > "$bad/sketch_arity.edits"
printf 'sketch alpha 1 0 0 0 1 1 1\n' > "$bad/sketch_alpha.edits"
printf 'alpha 1e308\n' > "$bad/huge_alpha.edits"     # an infinite cut cost
printf 'refine faces 1 2 1e-12\n' > "$bad/tiny_amount.edits"
printf 'alpha 1\nundo\nundo # one too many\n' > "$bad/undo.edits"
printf 'alpha 1\nundo\nalpha 0.8\nredo # forgotten by the edit before\n' > "$bad/redo.edits"
printf 'merge triangles 0 12946\n' > "$bad/triangle_range.edits"
echo "5 0 0 0 1 1 1" > "$bad/not_edges.polylines.txt"

# expect_error NAME STATUS PATTERN ARGS...: the program must exit with STATUS, and its
# last stderr line must start with "error:" and match PATTERN (extended regex). With
# --quiet, that line must be all of stderr.
expect_error() {
  local name="$1" status="$2" pattern="$3"; shift 3
  run "$name" "$@" --output-dir "$work/out_$name"
  local last
  last="$(tail -n 1 "$work/$name.err")"
  if [ "$rc" -ne "$status" ]; then
    fail "$name: exit status $rc, expected $status (stderr: $last)"; return
  fi
  if ! grep -q '^error: ' <<<"$last"; then
    fail "$name: last stderr line does not start with 'error:': '$last'"; return
  fi
  if ! grep -Eq -- "$pattern" <<<"$last"; then
    fail "$name: message '$last' does not match /$pattern/"; return
  fi
  if [ -e "$work/out_$name/summary.json" ]; then
    fail "$name: summary.json written despite the error"; return
  fi
  run "${name}_quiet" "$@" --output-dir "$work/out_$name" --quiet
  if [ "$rc" -ne "$status" ] || [ "$(wc -l < "$work/${name}_quiet.err")" -ne 1 ]; then
    fail "$name --quiet: expected status $status and exactly one stderr line, got $rc and:"
    cat "$work/${name}_quiet.err" >&2; return
  fi
  pass
  echo "  $name: $last"
}

echo "bad-input cases (name: message; bad mesh files are in script_bad_inputs.sh):"
expect_error rings_zero             2 '--rings'                     "$fandisk" --rings 0
expect_error rings_negative         2 '--rings'                     "$fandisk" --rings -3
expect_error rings_text             2 "--rings expects an integer"  "$fandisk" --rings abc
expect_error rings_fraction         2 "--rings expects an integer"  "$fandisk" --rings 1.5
expect_error rings_missing          2 "--rings expects a value"     "$fandisk" --rings
expect_error threshold_negative     2 '--strength-threshold'        "$fandisk" --strength-threshold -1
expect_error threshold_suffix       2 '--strength-threshold'        "$fandisk" --strength-threshold 1.5x
expect_error threshold_nan          2 '--strength-threshold'        "$fandisk" --strength-threshold nan
expect_error unknown_option         2 "unknown option '--unknown'"  "$fandisk" --unknown
expect_error two_meshes             2 'more than one input mesh'    "$fandisk" "$fandisk"
expect_error alpha_nan              2 '--alpha expects a finite'    "$fandisk" --alpha nan
expect_error alpha_inf              2 '--alpha expects a finite'    "$fandisk" --alpha inf
expect_error alpha_text             2 '--alpha expects a number'    "$fandisk" --alpha abc
expect_error alpha_missing          2 '--alpha expects a value'     "$fandisk" --alpha
expect_error gamma_negative         2 '--gamma must be >= 0'        "$fandisk" --gamma -1
expect_error gamma_nan              2 '--gamma expects a finite'    "$fandisk" --gamma nan
expect_error solver_unknown         2 "--solver must be .*'foo'"    "$fandisk" --solver foo
expect_error solver_empty           2 '--solver must be'            "$fandisk" --solver=
expect_error feature_edges_missing  1 'no such file'                "$fandisk" --feature-edges "$bad/missing.txt"
expect_error feature_edges_bad      1 'not a vertex of the mesh'    "$fandisk" --feature-edges "$bad/not_edges.polylines.txt"
expect_error edits_missing          1 'missing\.edits: no such file'  "$fandisk" --edits "$bad/missing.edits"
expect_error edits_verb             1 "verb\.edits:2: unknown verb 'frob'" "$fandisk" --edits "$bad/verb.edits"
expect_error edits_arity            1 'arity\.edits:3: alpha: wrong number of arguments' "$fandisk" --edits "$bad/arity.edits"
expect_error edits_ball_arity       1 "ball_arity\.edits:1: refine: a ball is 'ball X Y Z R'" "$fandisk" --edits "$bad/ball_arity.edits"
expect_error edits_number           1 "number\.edits:1: ball: 'zero' is not a number" "$fandisk" --edits "$bad/number.edits"
expect_error edits_infinite         1 "infinite\.edits:2: alpha: 'inf' is not a finite number" "$fandisk" --edits "$bad/infinite.edits"
expect_error edits_nan              1 "nan\.edits:1: scale: 'nan' is not a finite number" "$fandisk" --edits "$bad/nan.edits"
expect_error edits_undo_history     1 "undo_memory\.edits:4: undo: cannot take back line 1: the segmentation's history keeps 0 MiB of earlier states, and that edit's state was dropped" "$fandisk" --edits "$bad/undo_memory.edits" --undo-memory 0
expect_error undo_memory_negative   2 "--undo-memory must be an integer of MiB in 0 \.\. 1048576 \(got -1\)" "$fandisk" --undo-memory -1
expect_error edits_radius           1 'radius\.edits:1: ball: the radius must be > 0' "$fandisk" --edits "$bad/radius.edits"
expect_error edits_radius_negative  1 'radius_negative\.edits:1: ball: the radius must be > 0' "$fandisk" --edits "$bad/radius_negative.edits"
expect_error edits_face_range       1 'face_range\.edits:1: faces: face index 12946 is out of range \(the mesh file has 12946 faces\)' "$fandisk" --edits "$bad/face_range.edits"
expect_error edits_face_negative    1 "face_negative\.edits:1: faces: '-1' is not a face index" "$fandisk" --edits "$bad/face_negative.edits"
expect_error edits_redo             1 'redo\.edits:4: redo: no undone edit to redo' "$fandisk" --edits "$bad/redo.edits"
expect_error edits_triangle_range   1 'triangle_range\.edits:1: triangles: face index 12946 is out of range \(the mesh has 12946 triangles\)' "$fandisk" --edits "$bad/triangle_range.edits"
expect_error threads_negative       2 '--threads must be an integer in 0 \.\. 1024' "$fandisk" --threads -1
expect_error port_outside_edit      2 "--port is an option of 'edit'" "$fandisk" --port 8080
expect_error edit_port_range        2 '--port must be an integer in 0 \.\. 65535' edit "$fandisk" --port 70000
expect_error edit_web_root          1 "the editor's web page is not found" edit "$fandisk" --web-root "$bad/no_such_folder"
expect_error edit_missing_mesh      1 'no such file' edit "$bad/missing.off" --port 0
expect_error edits_region           1 "region\.edits:1: merge: expected a region" "$fandisk" --edits "$bad/region.edits"
expect_error edits_factor           1 'factor\.edits:1: scale: the factor must be >= 0' "$fandisk" --edits "$bad/factor.edits"
expect_error edits_sketch_arity     1 'sketch_arity\.edits:1: sketch: expected at least two points' "$fandisk" --edits "$bad/sketch_arity.edits"
expect_error edits_sketch_alpha     1 'sketch_alpha\.edits:1: sketch: alpha must be > 1' "$fandisk" --edits "$bad/sketch_alpha.edits"
expect_error edits_huge_alpha       1 'huge_alpha\.edits:1: alpha: the value must be 0 or of magnitude between 1e-9 and 1e9 \(got 1e\+308\)' "$fandisk" --edits "$bad/huge_alpha.edits"
expect_error edits_tiny_amount      1 'tiny_amount\.edits:1: refine: the value must be 0 or of magnitude between 1e-9 and 1e9' "$fandisk" --edits "$bad/tiny_amount.edits"
expect_error edits_undo             1 'undo\.edits:3: undo: no edit to undo' "$fandisk" --edits "$bad/undo.edits"
expect_error edits_no_value         2 '--edits expects a value'     "$fandisk" --edits
expect_error watershed_unknown      2 "--watershed must be anisotropic or geodesic \(got 'foo'\)" "$fandisk" --watershed foo
expect_error full_graph_value       2 '--full-graph takes no value' "$fandisk" --full-graph=1
expect_error smoothing_negative     2 '--smoothing-iterations must be an integer >= 0' "$fandisk" --smoothing-iterations -1
expect_error smoothing_text         2 '--smoothing-iterations expects an integer' "$fandisk" --smoothing-iterations many

echo "script_program_inputs: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
