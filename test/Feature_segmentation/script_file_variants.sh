#!/usr/bin/env bash
# Every file variant the readers accept, read by the program: OFF (OFF, COFF, 4OFF,
# comments, quads, duplicates, an open surface, an edge of four faces), OBJ (v/t/n, v//n with the ABC dataset's
# `vc` lines, negative indices, `v` with a weight, skipped statements), PLY (ascii; binary
# little and big endian with double coordinates, extra properties and an extra element
# with a list), STL (ascii, binary, binary whose header starts with "solid"). The files
# are the fuzzers' seeds (test/Feature_segmentation/fuzz/corpus). Each must give the
# mesh it holds: a cube (8 vertices, 12 triangles, closed), an open box (8, 10, 4 border
# edges) or a tetrahedron (4, 4), and all tetrahedra the same four points.
# Run by ctest with FS_BINARY_DIR and FS_SOURCE_DIR set.
set -uo pipefail

: "${FS_BINARY_DIR:?FS_BINARY_DIR must be set (the top build folder)}"
: "${FS_SOURCE_DIR:?FS_SOURCE_DIR must be set (the top source folder)}"
program="$FS_BINARY_DIR/demo/Feature_segmentation/feature_segmentation"
corpus="$FS_SOURCE_DIR/test/Feature_segmentation/fuzz/corpus"
[ -x "$program" ] || { echo "script_file_variants: the program is not built: $program" >&2; exit 1; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

json_int() { # json_int FILE SECTION KEY
  sed -n "/^  \"$2\": {/,/^  }/s/^    \"$3\": \([0-9][0-9]*\),\{0,1\}\$/\1/p" "$1"
}

# variant FILE VERTICES FACES BORDER_EDGES [NOTICE]
variant() {
  local file="$corpus/$1" name; name="$(basename "$1")"
  local out="$work/$name"
  timeout 60 "$program" "$file" --output-dir "$out" >/dev/null 2>"$work/$name.err"
  local rc=$? s="$out/summary.json"
  local got="$(json_int "$s" mesh vertices) $(json_int "$s" mesh faces) $(json_int "$s" mesh border_edges)"
  if [ "$rc" -ne 0 ]; then
    failed=$((failed + 1)); echo "FAIL: $1: exit status $rc: $(tail -n 1 "$work/$name.err")" >&2
  elif [ "$got" != "$2 $3 $4" ]; then
    failed=$((failed + 1)); echo "FAIL: $1: vertices, faces, border edges = $got, expected $2 $3 $4" >&2
  elif [ $# -ge 5 ] && ! grep -q "^notice: .*$5" "$work/$name.err"; then
    failed=$((failed + 1)); echo "FAIL: $1: no notice '$5'" >&2
  else
    passed=$((passed + 1)); echo "  $1: $got"
  fi
}

variant fuzz_read_off/cube_quads.off              8 12 0 'triangulated 6 faces'
variant fuzz_read_off/cube_triangles.off          8 12 0
variant fuzz_read_off/tetrahedron_coff.off        4 4 0
variant fuzz_read_off/four_d.off                  4 4 0
variant fuzz_read_off/open_box.off                8 10 4
variant fuzz_read_off/duplicates.off              8 12 0 'removed 1 duplicate faces'
# two tetrahedra sharing an edge (four faces on it): separated into two closed tetrahedra
variant fuzz_read_off/non_manifold_edge.off       8 8 0 'separated the faces of 1 non-manifold edges'
variant fuzz_read_obj/cube.obj                    8 12 0 'triangulated 6 faces'
variant fuzz_read_obj/abc_style.obj               4 4 0
variant fuzz_read_obj/negative.obj                4 4 0
variant fuzz_read_obj/texture.obj                 4 4 0
variant fuzz_read_ply/cube_ascii.ply              8 12 0 'triangulated 6 faces'
variant fuzz_read_ply/cube_le.ply                 8 12 0
variant fuzz_read_ply/tetrahedron_be.ply          4 4 0
variant fuzz_read_stl/cube_ascii.stl              8 12 0
variant fuzz_read_stl/cube_binary.stl             8 12 0
variant fuzz_read_stl/tetrahedron_solid_header.stl 4 4 0

# The same four points, whatever the format (4OFF's homogeneous coordinates divided out).
points() { awk '/^end_header$/ { p = 1; next } p && n++ < 4 { printf "%g %g %g\n", $1, $2, $3 }' \
           "$work/$1/segmentation.ply" | sort; }
reference="$(points tetrahedron_coff.off)"
for t in four_d.off abc_style.obj negative.obj texture.obj tetrahedron_be.ply tetrahedron_solid_header.stl; do
  if [ "$(points "$t")" = "$reference" ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1)); echo "FAIL: $t: points differ from tetrahedron_coff.off:" >&2; points "$t" >&2
  fi
done
[ "$(printf '0 0 0\n0 0 1\n0 1 0\n1 0 0')" = "$reference" ] && passed=$((passed + 1)) || {
  failed=$((failed + 1)); echo "FAIL: the tetrahedron is not the unit one: $reference" >&2; }

echo "script_file_variants: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
