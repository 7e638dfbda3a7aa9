#!/usr/bin/env bash
# The front door of the program, as a table: each bad mesh file (every format, every way
# a file can be wrong: not a file, empty, garbage, absurd or lying counts, truncation,
# NaN and infinity, indices out of range, malformed statements, lines of megabytes,
# wrong byte order, broken topology) must end, under a memory limit and a time limit,
# with exit status 1 and exactly one stderr line, "error: <file>[:<line>]: <reason>",
# matching the message given in the table. A hang, a crash, an allocation the limit
# refuses or any other message fails the case.
# Run by ctest with FS_BINARY_DIR (top build folder) set.
set -uo pipefail

: "${FS_BINARY_DIR:?FS_BINARY_DIR must be set (the top build folder)}"
program="$FS_BINARY_DIR/demo/Feature_segmentation/feature_segmentation"
[ -x "$program" ] || { echo "script_bad_inputs: the program is not built: $program" >&2; exit 1; }

work="$(mktemp -d)"
trap 'chmod -R u+rwx "$work" 2>/dev/null; rm -rf "$work"' EXIT
bad="$work/bad"
mkdir -p "$bad"
passed=0
failed=0

# case NAME FILE PATTERN: runs the program on FILE (one attempt, --quiet) with 10 s
# and 4 GB of address space at most; PATTERN is an extended regex the single line of
# stderr must match after "error: ".
case_() {
  local name="$1" file="$2" pattern="$3"
  local err="$work/$name.err"
  (ulimit -v "$address_space"; timeout 10 "$program" "$file" --output-dir "$work/out_$name" --quiet) \
    >/dev/null 2>"$err"
  local rc=$?
  local lines; lines="$(wc -l < "$err")"
  local line; line="$(head -n 1 "$err")"
  if [ "$rc" -ne 1 ]; then
    failed=$((failed + 1)); echo "FAIL: $name: exit status $rc, expected 1 (stderr: $line)" >&2
  elif [ "$lines" -ne 1 ]; then
    failed=$((failed + 1)); echo "FAIL: $name: $lines stderr lines, expected 1:" >&2; cat "$err" >&2
  elif ! grep -Eq -- "^error: .*$pattern" <<<"$line"; then
    failed=$((failed + 1)); echo "FAIL: $name: '$line' does not match /$pattern/" >&2
  elif [ -e "$work/out_$name/summary.json" ]; then
    failed=$((failed + 1)); echo "FAIL: $name: summary.json written despite the error" >&2
  else
    passed=$((passed + 1)); echo "  $name: ${line#error: $work/}"
  fi
}

p() { printf "$@"; }

# 4 GB of address space; a build with AddressSanitizer reserves terabytes of shadow
# memory up front, so there the limit is left to ASan (which refuses any allocation
# beyond 1 TB and reports it as a failure).
address_space=4000000
if grep -q __asan_init "$program"; then
  address_space=unlimited
  echo "  (AddressSanitizer build: no address-space limit)"
fi

# ---- not a readable mesh file ------------------------------------------------------
mkdir -p "$bad/a_directory.off"
mkfifo "$bad/fifo.off"
: > "$bad/zero_bytes.off"
p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$bad/plain_file"
echo "not a mesh" > "$bad/mesh.xyz"
case_ missing_file        "$bad/missing.off"             'missing\.off: no such file$'
case_ file_as_folder      "$bad/plain_file/mesh.off"     'no such file$'
case_ directory           "$bad/a_directory.off"         'is a directory, not a mesh file$'
case_ fifo                "$bad/fifo.off"                'is not a regular file'
case_ zero_bytes          "$bad/zero_bytes.off"          'zero_bytes\.off: the file is empty$'
case_ unknown_extension   "$bad/mesh.xyz"                "unknown format '\.xyz'"
case_ no_extension        "$bad/plain_file"              'unknown format \(no extension\)'
if [ "$(id -u)" -ne 0 ]; then
  cp "$bad/plain_file" "$bad/unreadable.off"; chmod 000 "$bad/unreadable.off"
  case_ unreadable        "$bad/unreadable.off"          'cannot be opened for reading \(Permission denied\)'
else
  echo "  unreadable: skipped (running as root, which reads any file)"
fi

# ---- OFF ---------------------------------------------------------------------------
p '\x89PNG\r\n\x1a\n\x00\x00' > "$bad/binary_garbage.off"
p 'OFF BINARY\n' > "$bad/binary.off"
p 'OFF\n2000000000 2000000000 0\n0 0 0\n' > "$bad/huge_header.off"
p 'OFF\n4 two 0\n' > "$bad/count_text.off"
p 'OFF\n4 2 0\n0 0 0\n1 0 0\n' > "$bad/lying_counts.off"
# Counts the size allows (the comments are long) that the content does not hold.
p 'OFF\n4 2 0\n0 0 0 # a vertex line with a long comment\n1 0 0 # and another one\n' > "$bad/truncated_vertices.off"
p 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2 # the last face is missing\n' > "$bad/truncated_faces.off"
p 'OFF\n4 2 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 1 2\n3 0 2 3\n' > "$bad/nan.off"
p 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 -inf 0\n0 0 1\n3 0 1 2\n3 0 2 3\n' > "$bad/inf.off"
p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e999 0\n3 0 1 2\n' > "$bad/overflow.off"
p 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 7\n' > "$bad/index_range.off"
p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n' > "$bad/index_negative.off"
p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1 # an edge\n' > "$bad/face_two.off"
p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0 # nothing\n' > "$bad/face_empty.off"
p 'OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2\n' > "$bad/face_short.off"
p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 x\n3 0 1 2\n' > "$bad/coordinate_text.off"
{ p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 '; head -c 3000000 /dev/zero | tr '\0' '7'; p '\n3 0 1 2\n'; } > "$bad/long_line.off"
p 'OFF\n0 0 0\n' > "$bad/no_faces.off"
case_ off_binary_garbage  "$bad/binary_garbage.off"      ":1: not an OFF file: the first word is '\?PNG'"
case_ off_binary          "$bad/binary.off"              ':1: binary OFF is not supported'
case_ off_huge_header     "$bad/huge_header.off"         ':2: the header announces 2000000000 vertices and 2000000000 faces, more than the 6 remaining bytes'
case_ off_count_text      "$bad/count_text.off"          ":2: expected the number of faces \(an integer >= 0\), found 'two'"
case_ off_lying_counts    "$bad/lying_counts.off"        ':2: the header announces 4 vertices and 2 faces, more than the 12 remaining bytes can hold'
case_ off_truncated_vertices "$bad/truncated_vertices.off" ':5: the file ends after 2 of the 4 vertices announced'
case_ off_truncated_faces "$bad/truncated_faces.off"     ':8: the file ends after 1 of the 2 faces announced'
case_ off_nan             "$bad/nan.off"                 ":5: has a NaN or infinite coordinate \('nan'\)"
case_ off_inf             "$bad/inf.off"                 ":5: has a NaN or infinite coordinate \('-inf'\)"
case_ off_overflow        "$bad/overflow.off"            ":5: has a NaN or infinite coordinate \('1e999'\)"
case_ off_index_range     "$bad/index_range.off"         ':8: face 1 refers to vertex 7 but the file has 4 vertices'
case_ off_index_negative  "$bad/index_negative.off"      ":6: face 0: '-1' is not a vertex index"
case_ off_face_two        "$bad/face_two.off"            ':6: face 0 has 2 vertices \(at least 3 are needed\)'
case_ off_face_empty      "$bad/face_empty.off"          ':6: face 0 has 0 vertices'
case_ off_face_short      "$bad/face_short.off"          ':7: face 0 announces 4 vertices but lists 3'
case_ off_coordinate_text "$bad/coordinate_text.off"     ":5: expected a z coordinate, found 'x'"
case_ off_long_line       "$bad/long_line.off"           ":5: has a NaN or infinite coordinate \('7777777777"
case_ off_no_faces        "$bad/no_faces.off"            'no_faces\.off: contains no faces$'

# ---- OBJ ---------------------------------------------------------------------------
p 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1^/1 2 3\n' > "$bad/reference.obj"
p 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n' > "$bad/zero.obj"
p 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n' > "$bad/relative.obj"
p 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$bad/range.obj"
p 'v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n' > "$bad/two_coordinates.obj"
p 'v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n' > "$bad/inf.obj"
p 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n' > "$bad/face_two.obj"
p '# only comments\nmtllib a.mtl\nvn 0 0 1\no thing\n' > "$bad/no_faces.obj"
case_ obj_reference       "$bad/reference.obj"           ":4: bad vertex reference '1\^/1' in a face"
case_ obj_zero            "$bad/zero.obj"                ':4: vertex references start at 1, found 0'
case_ obj_relative        "$bad/relative.obj"            ':4: the relative reference -4 goes before the first vertex \(3 vertices read so far\)'
case_ obj_range           "$bad/range.obj"               ':4: face 0 refers to vertex 9 but the file has 3 vertices'
case_ obj_two_coordinates "$bad/two_coordinates.obj"     ':2: expected a z coordinate, found the end of the line'
case_ obj_inf             "$bad/inf.obj"                 ":3: has a NaN or infinite coordinate \('-inf'\)"
case_ obj_face_two        "$bad/face_two.obj"            ':4: face 0 has 2 vertices \(at least 3 are needed\)'
case_ obj_no_faces        "$bad/no_faces.obj"            'no_faces\.obj: contains no faces$'

# ---- PLY ---------------------------------------------------------------------------
ply_header() { # ply_header FORMAT NV NF
  p 'ply\nformat %s 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\nelement face %s\nproperty list uchar int vertex_indices\nend_header\n' "$1" "$2" "$3"
}
p 'PLX\n' > "$bad/not_ply.ply"
p 'ply\nformat ascii 1.0\ne lement vertex 8\n' > "$bad/misspelt.ply"
p 'ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n' > "$bad/huge_count.ply"
p 'ply\nformat ascii 1.0\nelement vertex 3\n' > "$bad/no_end_header.ply"
p 'ply\nformat binary_middle_endian 1.0\nend_header\n' > "$bad/format.ply"
p 'ply\nformat ascii 1.0\nelement vertex 3\nproperty real x\nend_header\n' > "$bad/type.ply"
p 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n' > "$bad/no_x.ply"
p 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n' > "$bad/no_face_element.ply"
{ ply_header ascii 3 1; p '0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n'; } > "$bad/nan.ply"
{ ply_header ascii 3 1; p '0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n'; } > "$bad/range.ply"
{ ply_header ascii 3 2; p '0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'; } > "$bad/truncated.ply"
# Binary: three vertices (12 bytes each), one face (1 + 12 bytes) = 49 bytes.
{ ply_header binary_little_endian 3 1; head -c 30 /dev/zero; } > "$bad/binary_truncated.ply"
# Big-endian data in a file that says little endian: index 1 reads as 16777216.
{ ply_header binary_little_endian 3 1; head -c 36 /dev/zero; p '\x03\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00\x00\x02'; } > "$bad/byte_order.ply"
# A face list of 200 indices where 3 fit.
{ ply_header binary_little_endian 3 1; head -c 36 /dev/zero; p '\xc8\x00\x00\x00\x00\x01\x00\x00\x00\x02\x00\x00\x00'; } > "$bad/list_count.ply"
case_ ply_not_ply         "$bad/not_ply.ply"             ":1: not a PLY file \(the first line is not 'ply'\)"
case_ ply_misspelt        "$bad/misspelt.ply"            ":3: unknown header line starting with 'e'"
case_ ply_huge_count      "$bad/huge_count.ply"          'huge_count\.ply: the header announces more elements than the 0 bytes of the body can hold'
case_ ply_no_end_header   "$bad/no_end_header.ply"       ":4: the header has no 'end_header' line"
case_ ply_format          "$bad/format.ply"              ":2: unknown PLY format 'binary_middle_endian'"
case_ ply_type            "$bad/type.ply"                ":4: unknown property type 'real'"
case_ ply_no_x            "$bad/no_x.ply"                ":3: the vertex element has no 'x' coordinate"
case_ ply_no_face_element "$bad/no_face_element.ply"     "contains no faces \(no 'face' element in the header\)"
case_ ply_nan             "$bad/nan.ply"                 ':12: vertex 2 has a NaN or infinite coordinate'
case_ ply_range           "$bad/range.ply"               ':13: face 0 refers to vertex 5 but the file has 3 vertices'
case_ ply_truncated       "$bad/truncated.ply"           ':14: expected a list count, found the end of the file'
case_ ply_binary_truncated "$bad/binary_truncated.ply"   'the header announces more elements than the 30 bytes of the body can hold'
case_ ply_byte_order      "$bad/byte_order.ply"          'face 0 refers to vertex 16777216 but the file has 3 vertices'
case_ ply_list_count      "$bad/list_count.ply"          'in face 0: a list of 200 items does not fit in the rest of the file'

# ---- STL ---------------------------------------------------------------------------
p 'not an stl' > "$bad/short.stl"
{ head -c 80 /dev/zero; p '\x05\x00\x00\x00'; head -c 100 /dev/zero; } > "$bad/count.stl"
{ head -c 80 /dev/zero; p '\x02\x00\x00\x00'; head -c 50 /dev/zero;
  head -c 12 /dev/zero; p '\x00\x00\xc0\x7f'; head -c 34 /dev/zero; } > "$bad/nan_binary.stl"
p 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\nendsolid s\n' > "$bad/endloop.stl"
p 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid s\n' > "$bad/two_vertices.stl"
p 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 inf 0\nendloop\nendfacet\nendsolid s\n' > "$bad/inf_ascii.stl"
p 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n' > "$bad/truncated_ascii.stl"
case_ stl_short           "$bad/short.stl"               'not an STL file \(10 bytes: too short for a binary STL header'
case_ stl_count           "$bad/count.stl"               'its header announces 5 triangles, which take 334 bytes, but the file has 184'
case_ stl_nan_binary      "$bad/nan_binary.stl"          'triangle 2 has a NaN or infinite coordinate'
case_ stl_endloop         "$bad/endloop.stl"             ":7: expected 'vertex' or 'endloop', found 'endfacet'"
case_ stl_two_vertices    "$bad/two_vertices.stl"        ':6: a facet with 2 vertices \(at least 3 are needed\)'
case_ stl_inf_ascii       "$bad/inf_ascii.stl"           ":6: has a NaN or infinite coordinate \('inf'\)"
case_ stl_truncated_ascii "$bad/truncated_ascii.stl"     "expected 'vertex' or 'endloop', found the end of the file"

# ---- a well-formed file that is not a surface ----------------------------------------
p 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0.5 2 0\n3 0 1 2\n3 1 0 3\n' > "$bad/folded.off"
p 'OFF\n4 2 0\n0 0 0\n1 1 1\n2 2 2\n0 0 1\n3 0 1 2\n3 0 2 3\n' > "$bad/collinear.off"
p 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n' > "$bad/repeated_index.off"
p 'OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n4 0 1 2 3\n' > "$bad/same_position.off"
case_ folded              "$bad/folded.off"              'face 0 \(line 7\) and face 1 \(line 8\) overlap'
case_ collinear           "$bad/collinear.off"           'face 0 \(line 7\) is degenerate \(its points are collinear: zero area\)'
case_ repeated_index      "$bad/repeated_index.off"      'face 0 \(line 6\) is degenerate \(it uses a vertex twice\)'
case_ same_position       "$bad/same_position.off"       'face 0 \(line 7\) is degenerate \(two of its vertices are at the same position\)'
# A pentagon whose last edge crosses its second (found by fuzzing: CGAL 5.5's triangulation
# of such a polygon reads uninitialised memory).
p 'OFF\n5 1 0\n0 0 0\n2 0 0\n0 2 0\n2 2 0\n1 3 0\n5 0 1 2 3 4\n' > "$bad/self_intersecting.off"
case_ self_intersecting   "$bad/self_intersecting.off"   'face 0 \(a polygon of 5 vertices\) cannot be triangulated: it is not a simple polygon in its plane'

echo "script_bad_inputs: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
