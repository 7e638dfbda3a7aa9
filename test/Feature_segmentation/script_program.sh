#!/usr/bin/env bash
# Tests the command-line program `feature_segmentation`: a run on fandisk whose outputs
# must be complete, well-formed, consistent with the mesh and deterministic, a quad mesh
# that must be triangulated with a notice, and every kind of bad input and bad option,
# each of which must end in one "error:" line on stderr and the documented exit status
# (1 for bad input, 2 for a bad command line), never a crash or a hang.
# Run by ctest with FS_BINARY_DIR (top build folder) and FS_MESH_DIR set.
set -uo pipefail

: "${FS_BINARY_DIR:?FS_BINARY_DIR must be set (the top build folder)}"
: "${FS_MESH_DIR:?FS_MESH_DIR must be set (the folder holding fandisk.off)}"
program="$FS_BINARY_DIR/demo/Feature_segmentation/feature_segmentation"
fandisk="$FS_MESH_DIR/fandisk.off"

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }
check() { # check DESCRIPTION COMMAND...: passes if the command succeeds
  local what="$1"; shift
  if "$@"; then pass; else fail "$what"; fi
}

if [ ! -x "$program" ]; then
  echo "script_program: the program is not built: $program" >&2
  exit 1
fi
if [ ! -f "$fandisk" ]; then
  echo "script_program: the default model is missing: $fandisk" >&2
  exit 1
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# run NAME ARGS...: runs the program with a time limit; sets $rc, $work/NAME.out/.err
run() {
  local name="$1"; shift
  timeout 60 "$program" "$@" >"$work/$name.out" 2>"$work/$name.err"
  rc=$?
}

# json_int FILE SECTION KEY: the integer value of "KEY" inside the object "SECTION"
# (SECTION empty: a top-level key). The summary is written one key per line.
json_int() {
  local file="$1" section="$2" key="$3"
  if [ -z "$section" ]; then
    sed -n "s/^  \"$key\": \([0-9][0-9]*\),\{0,1\}\$/\1/p" "$file"
  else
    sed -n "/^  \"$section\": {/,/^  }/s/^    \"$key\": \([0-9][0-9]*\),\{0,1\}\$/\1/p" "$file"
  fi
}

# A polylines file is well-formed if every line is "n x1 y1 z1 ... xn yn zn", n >= 2.
polylines_well_formed() {
  awk '{ if ($1 !~ /^[0-9]+$/ || $1 < 2 || NF != 1 + 3 * $1) { print "line " NR ": bad record"; bad = 1 } }
       END { exit bad }' "$1"
}

# ---- the default run on fandisk --------------------------------------------------------
out="$work/fandisk"
run fandisk "$fandisk" --output-dir "$out"
check "fandisk: exit status 0 (got $rc; stderr: $(tail -n 1 "$work/fandisk.err"))" [ "$rc" -eq 0 ]
for f in feature_lines.polylines.txt feature_lines.obj summary.json; do
  check "fandisk: $f written" [ -s "$out/$f" ]
done
check "fandisk: no error line on stderr" bash -c "! grep -q '^error:' '$work/fandisk.err'"

# The OFF file as one token per line, comments dropped: "OFF", V, F, E, coordinates, faces.
awk '{ sub(/#.*/, ""); for (i = 1; i <= NF; i++) print $i }' "$fandisk" > "$work/fandisk.tokens"
token() { sed -n "$(($1 + 1))p" "$work/fandisk.tokens"; }
header_vertices="$(token 1)"
header_faces="$(token 2)"
summary="$out/summary.json"
if command -v python3 >/dev/null 2>&1; then
  check "fandisk: summary.json is valid JSON" python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$summary"
fi
v="$(json_int "$summary" mesh vertices)"
f="$(json_int "$summary" mesh faces)"
e="$(json_int "$summary" mesh edges)"
total="$(json_int "$summary" feature_lines total)"
ridges="$(json_int "$summary" feature_lines ridges)"
valleys="$(json_int "$summary" feature_lines valleys)"
user="$(json_int "$summary" feature_lines user)"
fedges="$(json_int "$summary" "" feature_edges)"
check "fandisk: summary vertices ($v) = OFF header ($header_vertices)" [ "$v" = "$header_vertices" ]
check "fandisk: summary faces ($f) = OFF header ($header_faces)" [ "$f" = "$header_faces" ]
# A closed triangle mesh: 3F = 2E, and Euler's formula for fandisk (genus 0): V - E + F = 2.
check "fandisk: edges ($e) = 3F/2" [ "$e" = "$((3 * header_faces / 2))" ]
check "fandisk: Euler characteristic 2" [ "$((v - e + f))" -eq 2 ]
check "fandisk: feature lines found (total $total)" [ -n "$total" ] && [ "${total:-0}" -gt 0 ]
check "fandisk: ridges + valleys + user = total" [ "$((ridges + valleys + user))" -eq "$total" ]
check "fandisk: no user lines without --feature-edges" [ "$user" -eq 0 ]
check "fandisk: feature edges counted (${fedges:-none})" [ "${fedges:-0}" -gt 0 ]
check "fandisk: feature edges <= edges" [ "${fedges:-0}" -le "$e" ]
for stage in load curvature feature_lines total; do
  check "fandisk: seconds.$stage in summary" grep -Eq "^    \"$stage\": [0-9.e+-]+,?\$" "$summary"
done
lines="$(wc -l < "$out/feature_lines.polylines.txt")"
check "fandisk: polylines lines ($lines) = feature lines in summary ($total)" [ "$lines" -eq "$total" ]
check "fandisk: polylines file well-formed" polylines_well_formed "$out/feature_lines.polylines.txt"
obj_lines="$(grep -c '^l ' "$out/feature_lines.obj")"
obj_vertices="$(grep -c '^v ' "$out/feature_lines.obj")"
poly_points="$(awk '{ s += $1 } END { print s + 0 }' "$out/feature_lines.polylines.txt")"
closed="$(awk '{ if ($2 == $(NF - 2) && $3 == $(NF - 1) && $4 == $NF) c++ } END { print c + 0 }' "$out/feature_lines.polylines.txt")"
check "fandisk: OBJ l records ($obj_lines) = feature lines ($total)" [ "$obj_lines" -eq "$total" ]
check "fandisk: OBJ v records ($obj_vertices) = polyline points ($poly_points) - closed repeats ($closed)" \
  [ "$obj_vertices" -eq "$((poly_points - closed))" ]
check "fandisk: OBJ indices within 1..$obj_vertices" \
  awk -v n="$obj_vertices" '/^l /{ for (i = 2; i <= NF; i++) if ($i < 1 || $i > n) exit 1 }' "$out/feature_lines.obj"

# Deterministic: a second run gives identical feature-line files.
run fandisk_again "$fandisk" --output-dir "$work/fandisk_again" --quiet
check "fandisk again: exit status 0" [ "$rc" -eq 0 ]
check "fandisk again: --quiet prints nothing on stderr" [ ! -s "$work/fandisk_again.err" ]
for f in feature_lines.polylines.txt feature_lines.obj; do
  check "fandisk: $f identical over two runs" cmp -s "$out/$f" "$work/fandisk_again/$f"
done

# Options change what is detected: no ridges -> only valleys; a huge threshold -> none.
run no_ridges "$fandisk" --output-dir "$work/no_ridges" --no-ridges --quiet
check "--no-ridges: exit status 0" [ "$rc" -eq 0 ]
check "--no-ridges: 0 ridges, $valleys valleys" \
  [ "$(json_int "$work/no_ridges/summary.json" feature_lines ridges)" = 0 ] && \
  [ "$(json_int "$work/no_ridges/summary.json" feature_lines valleys)" = "$valleys" ]
run no_lines "$fandisk" --output-dir "$work/no_lines" --strength-threshold 1e9 --rings 1 --quiet
check "--strength-threshold 1e9: exit status 0" [ "$rc" -eq 0 ]
check "--strength-threshold 1e9: no feature lines" \
  [ "$(json_int "$work/no_lines/summary.json" feature_lines total)" = 0 ]
check "--strength-threshold 1e9: empty polylines file" [ ! -s "$work/no_lines/feature_lines.polylines.txt" ]
check "--rings 1 recorded in summary" grep -q '^    "rings": 1,$' "$work/no_lines/summary.json"

# User feature lines: the first two edges of face 0 of fandisk, as one polyline.
first_face=$((4 + 3 * header_vertices)) # token index of face 0's vertex count
point() { echo "$(token $((4 + 3 * $1))) $(token $((5 + 3 * $1))) $(token $((6 + 3 * $1)))"; }
a="$(token $((first_face + 1)))"; b="$(token $((first_face + 2)))"; c="$(token $((first_face + 3)))"
echo "3 $(point "$a") $(point "$b") $(point "$c")" > "$work/user.polylines.txt"
run user "$fandisk" --output-dir "$work/user" --strength-threshold 1e9 --feature-edges "$work/user.polylines.txt" --quiet
check "--feature-edges: exit status 0 (stderr: $(tail -n 1 "$work/user.err"))" [ "$rc" -eq 0 ]
check "--feature-edges: 1 user line" [ "$(json_int "$work/user/summary.json" feature_lines user)" = 1 ]
check "--feature-edges: 2 feature edges" [ "$(json_int "$work/user/summary.json" "" feature_edges)" = 2 ]
check "--feature-edges: the user line is written" [ "$(wc -l < "$work/user/feature_lines.polylines.txt")" -eq 1 ]

# --help: usage on stdout, status 0.
run help --help
check "--help: exit status 0" [ "$rc" -eq 0 ]
check "--help: usage on stdout" grep -q '^Usage: feature_segmentation' "$work/help.out"

# ---- a quad mesh: triangulated, with a notice -------------------------------------------
# An open box of five unit squares (no top): 8 vertices, 5 quads -> 10 triangles.
cat > "$work/box.off" <<'EOF'
OFF
8 5 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
EOF
run quad "$work/box.off" --output-dir "$work/quad"
check "quad mesh: exit status 0 (stderr: $(tail -n 1 "$work/quad.err"))" [ "$rc" -eq 0 ]
check "quad mesh: notice about triangulation" grep -q '^notice: .*triangulated 5 faces' "$work/quad.err"
check "quad mesh: 10 triangles" [ "$(json_int "$work/quad/summary.json" mesh faces)" = 10 ]
check "quad mesh: 4 border edges" [ "$(json_int "$work/quad/summary.json" mesh border_edges)" = 4 ]

# ---- the other formats -------------------------------------------------------------------
# fandisk as OBJ: same mesh, same feature lines as from the OFF file.
awk -v V="$header_vertices" '
  NR > 4 && NR <= 4 + 3 * V { c[(NR - 5) % 3] = $1; if ((NR - 4) % 3 == 0) print "v", c[0], c[1], c[2] }
  NR > 4 + 3 * V { if (k == 0) { k = $1; s = "f" } else { s = s " " ($1 + 1); if (--k == 0) print s } }
' "$work/fandisk.tokens" > "$work/fandisk.obj"
run obj "$work/fandisk.obj" --output-dir "$work/obj" --quiet
check "fandisk.obj: exit status 0 (stderr: $(tail -n 1 "$work/obj.err"))" [ "$rc" -eq 0 ]
check "fandisk.obj: same vertex count as the OFF file" \
  [ "$(json_int "$work/obj/summary.json" mesh vertices)" = "$header_vertices" ]
check "fandisk.obj: same feature lines as the OFF file" \
  cmp -s "$work/obj/feature_lines.polylines.txt" "$out/feature_lines.polylines.txt"

# Binary STL, written byte by byte: 80-byte header, triangle count, then per triangle a
# normal, three points (little-endian floats) and 2 attribute bytes.
f0='\x00\x00\x00\x00'; f1='\x00\x00\x80\x3f'; fnan='\x00\x00\xc0\x7f'
stl_triangle() { printf "$f0$f0$f0$1$2$3"'\x00\x00'; }
{ head -c 80 /dev/zero; printf '\x04\x00\x00\x00'
  stl_triangle "$f0$f0$f0" "$f0$f1$f0" "$f1$f0$f0"
  stl_triangle "$f0$f0$f0" "$f0$f0$f1" "$f0$f1$f0"
  stl_triangle "$f0$f0$f0" "$f1$f0$f0" "$f0$f0$f1"
  stl_triangle "$f1$f0$f0" "$f0$f1$f0" "$f0$f0$f1"; } > "$work/tetrahedron.stl"
{ head -c 80 /dev/zero; printf '\x02\x00\x00\x00'
  stl_triangle "$f0$f0$f0" "$f0$f1$f0" "$f1$f0$f0"
  stl_triangle "$f0$f0$f0" "$f0$f0$fnan" "$f0$f1$f0"; } > "$work/nan_binary.stl"
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
mkdir -p "$bad/a_directory.off"
printf 'OFF\n0 0 0\n' > "$bad/empty.off"
: > "$bad/zero_bytes.off"
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 1 2\n3 0 2 3\n' > "$bad/nan.off"
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 inf 0\n0 0 1\n3 0 1 2\n3 0 2 3\n' > "$bad/inf.off"
printf 'v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n' > "$bad/inf.obj"
# Three triangles on the edge (0, 1).
printf 'OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n' > "$bad/non_manifold_edge.off"
# Two triangles folded onto each other across the edge (0, 1).
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0.5 2 0\n3 0 1 2\n3 1 0 3\n' > "$bad/folded.off"
printf 'OFF\n4 2 0\n0 0 0\n1 1 1\n2 2 2\n0 0 1\n3 0 1 2\n3 0 2 3\n' > "$bad/degenerate.off"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n' > "$bad/repeated_index.off"
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n' > "$bad/truncated.off"
printf 'OFF\n2000000000 2000000000 0\n0 0 0\n' > "$bad/huge_header.off"
head -c 4096 /dev/urandom > "$bad/garbage.off"
head -c 4096 /dev/urandom > "$bad/garbage.ply"
head -c 4096 /dev/urandom > "$bad/garbage.stl"
echo "not a mesh" > "$bad/mesh.xyz"
echo "not a mesh" > "$bad/no_extension"
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

echo "bad-input cases (name: message):"
expect_error missing_file           1 'no such file'                "$bad/missing.off"
expect_error missing_folder         1 'no such file'                "$bad/no/such/folder/mesh.off"
expect_error directory              1 'is a directory'              "$bad/a_directory.off"
expect_error zero_bytes             1 'empty'                       "$bad/zero_bytes.off"
expect_error garbage_off            1 'cannot be read as off'       "$bad/garbage.off"
expect_error garbage_ply            1 'cannot be read as ply'       "$bad/garbage.ply"
expect_error garbage_stl            1 'cannot be read as stl'       "$bad/garbage.stl"
expect_error unknown_extension      1 "unknown format '\.xyz'"      "$bad/mesh.xyz"
expect_error no_extension           1 'unknown format'              "$bad/no_extension"
expect_error empty_mesh             1 'contains no faces'           "$bad/empty.off"
expect_error nan_coordinate         1 'NaN or infinite'             "$bad/nan.off"
expect_error inf_coordinate         1 'NaN or infinite'             "$bad/inf.off"
expect_error inf_coordinate_obj     1 'NaN or infinite'             "$bad/inf.obj"
expect_error nan_coordinate_stl     1 'triangle 2 has a NaN'        "$work/nan_binary.stl"
expect_error non_manifold_edge      1 'shared by 3 faces'           "$bad/non_manifold_edge.off"
expect_error folded_faces           1 'overlap'                     "$bad/folded.off"
expect_error degenerate_triangle    1 'degenerate'                  "$bad/degenerate.off"
expect_error repeated_index         1 'degenerate'                  "$bad/repeated_index.off"
expect_error truncated              1 'malformed or truncated'      "$bad/truncated.off"
expect_error huge_header            1 'cannot be read'              "$bad/huge_header.off"
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
expect_error feature_edges_missing  1 'no such file'                "$fandisk" --feature-edges "$bad/missing.txt"
expect_error feature_edges_bad      1 'not a vertex of the mesh'    "$fandisk" --feature-edges "$bad/not_edges.polylines.txt"

echo "script_program: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
