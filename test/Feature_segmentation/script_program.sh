#!/usr/bin/env bash
# Tests the command-line program `feature_segmentation`: a run on fandisk whose outputs
# (feature lines, segmentation, summary) must be complete, well-formed, consistent with
# the mesh and deterministic, the segmentation options, a quad mesh that must be
# triangulated with a notice, patch files that follow the input file's order through
# the reader's repairs, and every kind of bad input and bad option,
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

# json_get FILE KEY...: the value at the path KEY... of the JSON file (object keys,
# array indices), strings as they are, other values as JSON text; nothing if absent.
json_get() {
  python3 - "$@" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
for k in sys.argv[2:]:
    if isinstance(v, list) and k.isdigit() and int(k) < len(v): v = v[int(k)]
    elif isinstance(v, dict) and k in v: v = v[k]
    else: sys.exit(0)
print(v if isinstance(v, str) else json.dumps(v))
PY
}

# json_int FILE SECTION KEY: the value of "KEY" inside the object "SECTION" (SECTION
# empty: a top-level key); json_number the same (kept for readability of the checks).
json_int() { if [ -z "$2" ]; then json_get "$1" "$3"; else json_get "$1" "$2" "$3"; fi; }
json_number() { json_get "$1" "$2" "$3"; }

# ids_cover FILE N: every line is an integer in [0, N) and every such integer occurs.
ids_cover() {
  awk -v n="$2" '$0 !~ /^[0-9]+$/ || $1 >= n { bad = 1; exit } { seen[$1] = 1 }
                 END { if (bad) exit 1; for (i = 0; i < n; i++) if (!(i in seen)) exit 1 }' "$1"
}
# ids_in_range FILE N: every line is an integer in [0, N).
ids_in_range() {
  awk -v n="$2" '$0 !~ /^[0-9]+$/ || $1 >= n { bad = 1 } END { exit bad }' "$1"
}

# ply_header_ok FILE VERTICES FACES: an ASCII PLY file with these element counts, the
# face properties of segmentation.ply, and one data line per element; every face line
# is "3 i j k patch_id red green blue" with its vertex indices in range.
ply_header_ok() {
  awk -v nv="$2" -v nf="$3" '
    NR == 1 { if ($0 != "ply") exit 1; next }
    !body {
      if ($0 == "format ascii 1.0") format = 1
      if ($1 == "element" && $2 == "vertex") v = $3
      if ($1 == "element" && $2 == "face") { f = $3; in_face = 1 }
      if (in_face && $1 == "property") props = props " " $NF ":" $2
      if ($0 == "end_header") body = 1
      next
    }
    { row++ }
    row > nv && (NF != 8 || $1 != 3 || $2 >= nv || $3 >= nv || $4 >= nv) { bad = 1 }
    END {
      if (!format || v != nv || f != nf || row != nv + nf || bad) exit 1
      if (props != " vertex_indices:list patch_id:int red:uchar green:uchar blue:uchar") exit 1
    }' "$1"
}

# A polylines file is well-formed if every line is "n x1 y1 z1 ... xn yn zn", n >= 2.
polylines_well_formed() {
  awk '{ if ($1 !~ /^[0-9]+$/ || $1 < 2 || NF != 1 + 3 * $1) { print "line " NR ": bad record"; bad = 1 } }
       END { exit bad }' "$1"
}

# ---- fandisk with its crest lines ------------------------------------------------------
# At the defaults a clean CAD tessellation such as fandisk is cut along its creases and
# curvature discontinuities and gets no crest lines (checked below, "the default run");
# the runs that check feature lines, curves and smoothing ask for the paper's crest lines
# too, with --crest-lines-on-clean-tessellations ($crest).
crest=--crest-lines-on-clean-tessellations
out="$work/fandisk"
run fandisk "$fandisk" --output-dir "$out" $crest
check "fandisk: exit status 0 (got $rc; stderr: $(tail -n 1 "$work/fandisk.err"))" [ "$rc" -eq 0 ]
for f in feature_lines.polylines.txt feature_lines.obj summary.json segmentation.ply \
         face_patches.txt vertex_patches.txt boundaries.polylines.txt segmentation_refined.ply; do
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
check "fandisk: feature lines found (total $total)" [ -n "$total" -a "${total:-0}" -gt 0 ]
check "fandisk: ridges + valleys + user = total" [ "$((ridges + valleys + user))" -eq "$total" ]
check "fandisk: no user lines without --feature-edges" [ "$user" -eq 0 ]
check "fandisk: feature edges counted (${fedges:-none})" [ "${fedges:-0}" -gt 0 ]
check "fandisk: feature edges <= edges" [ "${fedges:-0}" -le "$e" ]
for stage in load segmentation total; do
  check "fandisk: seconds.$stage in summary" [ -n "$(json_get "$summary" seconds "$stage")" ]
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

# The segmentation: patch count, cut cost and options in the summary; one patch id per
# vertex and per face of the input file; the PLY mesh with a patch and colour per face.
patches="$(json_int "$summary" segmentation patches)"
cut_cost="$(json_number "$summary" segmentation cut_cost)"
check "fandisk: segmentation.patches in summary (${patches:-none})" [ "${patches:-0}" -ge 1 ]
check "fandisk: segmentation.cut_cost in summary (${cut_cost:-none})" [ -n "$cut_cost" ]
check "fandisk: segmentation.solver_seconds in summary" \
  [ -n "$(json_number "$summary" segmentation solver_seconds)" ]
check "fandisk: options.alpha = 0.6 (the default)" [ "$(json_number "$summary" options alpha)" = 0.6 ]
check "fandisk: options.gamma = 0.05 (the default)" [ "$(json_number "$summary" options gamma)" = 0.05 ]
check "fandisk: options.solver = gaec+klj (the default)" [ "$(json_get "$summary" options solver)" = gaec+klj ]
# One patch: nothing is cut, so the cut cost is exactly 0; more: a minimiser kept a
# partition cheaper than the single patch (cost 0), so the cost is negative.
if [ "${patches:-0}" -eq 1 ]; then
  check "fandisk: one patch, cut cost 0 (got $cut_cost)" awk -v c="$cut_cost" 'BEGIN { exit !(c == 0) }'
else
  check "fandisk: $patches patches, cut cost < 0 (got $cut_cost)" awk -v c="$cut_cost" 'BEGIN { exit !(c < 0) }'
fi
check "fandisk: vertex_patches.txt has one line per file vertex ($header_vertices)" \
  [ "$(wc -l < "$out/vertex_patches.txt")" -eq "$header_vertices" ]
check "fandisk: face_patches.txt has one line per file face ($header_faces)" \
  [ "$(wc -l < "$out/face_patches.txt")" -eq "$header_faces" ]
# Vertex labels are the clustering's, numbered 0..patches-1 without gaps. A face takes
# the majority of its vertices' patches, so a patch of a few scattered vertices may own
# no face: face ids are only checked to be in range.
check "fandisk: vertex ids cover exactly [0, $patches)" ids_cover "$out/vertex_patches.txt" "$patches"
check "fandisk: face ids in [0, $patches)" ids_in_range "$out/face_patches.txt" "$patches"
check "fandisk: segmentation.ply: ASCII, $v vertices, $f faces, patch_id and colour per face" \
  ply_header_ok "$out/segmentation.ply" "$v" "$f"
# Nothing is repaired in fandisk, so the mesh keeps the file's face order: the PLY's
# patch_id column is face_patches.txt.
check "fandisk: segmentation.ply patch ids = face_patches.txt" \
  cmp -s <(awk -v nv="$v" 'p && ++row > nv { print $5 } /^end_header$/ { p = 1 }' "$out/segmentation.ply") \
         "$out/face_patches.txt"
check "fandisk: equal patch ids have equal colours in segmentation.ply" \
  awk -v nv="$v" 'p && ++row > nv { c = $6 " " $7 " " $8; if (($5 in col) && col[$5] != c) exit 1; col[$5] = c }
                  /^end_header$/ { p = 1 }' "$out/segmentation.ply"
# The boundaries: one polyline per curve; the smoothing never raises their anisotropic
# length (its energy); the refined mesh splits the faces the curves cross, so it has at
# least the mesh's vertices and faces, every face in a patch of the clustering's range.
curves="$(json_int "$summary" boundaries curves)"
check "fandisk: boundaries.curves in summary (${curves:-none}), some for $patches patches" \
  [ "${curves:-0}" -ge 1 ]
check "fandisk: boundaries.polylines.txt has one line per curve ($curves)" \
  [ "$(wc -l < "$out/boundaries.polylines.txt")" -eq "${curves:-0}" ]
check "fandisk: boundaries.polylines.txt well-formed" polylines_well_formed "$out/boundaries.polylines.txt"
check "fandisk: smoothing_iterations = 20 (the library's default) in options" \
  [ "$(json_int "$summary" options smoothing_iterations)" = 20 ]
check "fandisk: smoothing ran (iterations in [1, 20])" \
  [ "$(json_int "$summary" boundaries smoothing_iterations)" -ge 1 -a \
   "$(json_int "$summary" boundaries smoothing_iterations)" -le 20 ]
check "fandisk: smoothing does not raise the anisotropic length" \
  awk -v a="$(json_number "$summary" boundaries anisotropic_length_after)" \
      -v b="$(json_number "$summary" boundaries anisotropic_length_before)" 'BEGIN { exit !(a != "" && a <= b) }'
check "fandisk: smoothing_seconds and seconds.smoothing in summary" \
  [ -n "$(json_number "$summary" boundaries smoothing_seconds)" -a -n "$(json_get "$summary" seconds smoothing)" ]
refined_v="$(sed -n 's/^element vertex \([0-9]*\)$/\1/p' "$out/segmentation_refined.ply")"
refined_f="$(sed -n 's/^element face \([0-9]*\)$/\1/p' "$out/segmentation_refined.ply")"
check "fandisk: segmentation_refined.ply: ${refined_v:-?} >= $v vertices, ${refined_f:-?} >= $f faces" \
  [ "${refined_v:-0}" -ge "$v" -a "${refined_f:-0}" -ge "$f" ]
check "fandisk: segmentation_refined.ply well-formed (triangles, patch_id and colour per face)" \
  ply_header_ok "$out/segmentation_refined.ply" "${refined_v:-0}" "${refined_f:-0}"
check "fandisk: refined_faces in summary = the refined PLY's faces" \
  [ "$(json_int "$summary" boundaries refined_faces)" = "$refined_f" ]
check "fandisk: refined patch ids in [0, $patches)" \
  ids_in_range <(awk -v nv="$refined_v" 'p && ++row > nv { print $5 } /^end_header$/ { p = 1 }' "$out/segmentation_refined.ply") "$patches"
check "fandisk: progress lines on stderr" grep -q '^progress: smoothing done in [0-9.]* s$' "$work/fandisk.err"

# CGAL's PLY reader (read_polygon_soup, through the program itself) reads it back: the
# same mesh, so the same feature lines.
run ply_back "$out/segmentation.ply" --output-dir "$work/ply_back" $crest --quiet
check "segmentation.ply read back: exit status 0 (stderr: $(tail -n 1 "$work/ply_back.err"))" [ "$rc" -eq 0 ]
check "segmentation.ply read back: $v vertices, $f faces" \
  [ "$(json_int "$work/ply_back/summary.json" mesh vertices)" = "$v" -a \
   "$(json_int "$work/ply_back/summary.json" mesh faces)" = "$f" ]
check "segmentation.ply read back: same feature lines" \
  cmp -s "$work/ply_back/feature_lines.polylines.txt" "$out/feature_lines.polylines.txt"

# Deterministic: a second run gives identical feature-line and segmentation files.
run fandisk_again "$fandisk" --output-dir "$work/fandisk_again" $crest --quiet
check "fandisk again: exit status 0" [ "$rc" -eq 0 ]
check "fandisk again: --quiet prints nothing on stderr" [ ! -s "$work/fandisk_again.err" ]
for f in feature_lines.polylines.txt feature_lines.obj segmentation.ply face_patches.txt \
         vertex_patches.txt boundaries.polylines.txt segmentation_refined.ply; do
  check "fandisk: $f identical over two runs" cmp -s "$out/$f" "$work/fandisk_again/$f"
done

# ---- the default run on fandisk --------------------------------------------------------
# A clean CAD tessellation: its feature edges are exactly its crease edges (876 creases
# and the 50 edges of its blends' tangent lines, as test_tangent_discontinuities finds),
# no crest line; every patch boundary runs along them, so there is no boundary curve to
# smooth, and the 21 patches are the regions they bound (every one owns faces).
run default "$fandisk" --output-dir "$work/default" --quiet
ds="$work/default/summary.json"
check "default: exit status 0 (stderr: $(tail -n 1 "$work/default.err"))" [ "$rc" -eq 0 ]
check "default: no crest line on a clean tessellation ($(json_int "$ds" feature_lines total))" \
  [ "$(json_int "$ds" feature_lines total)" = 0 -a ! -s "$work/default/feature_lines.polylines.txt" ]
check "default: 926 crease edges, the only feature edges" \
  [ "$(json_int "$ds" "" crease_edges)" = 926 -a "$(json_int "$ds" "" feature_edges)" = 926 ]
check "default: 21 patches ($(json_int "$ds" segmentation patches))" [ "$(json_int "$ds" segmentation patches)" = 21 ]
check "default: no boundary curve (every boundary is a crease)" \
  [ "$(json_int "$ds" boundaries curves)" = 0 -a ! -s "$work/default/boundaries.polylines.txt" ]
check "default: face ids cover exactly [0, 21)" ids_cover "$work/default/face_patches.txt" 21
check "default: options.crest_lines_on_clean_tessellations false in summary" \
  [ "$(json_get "$ds" options crest_lines_on_clean_tessellations)" = false ]
check "--crest-lines-on-clean-tessellations: recorded in summary" \
  [ "$(json_get "$summary" options crest_lines_on_clean_tessellations)" = true ]

# Options change what is detected: no ridges -> only valleys; a huge threshold -> none.
run no_ridges "$fandisk" --output-dir "$work/no_ridges" $crest --no-ridges --quiet
check "--no-ridges: exit status 0" [ "$rc" -eq 0 ]
check "--no-ridges: 0 ridges, $valleys valleys" \
  [ "$(json_int "$work/no_ridges/summary.json" feature_lines ridges)" = 0 -a \
   "$(json_int "$work/no_ridges/summary.json" feature_lines valleys)" = "$valleys" ]
run no_lines "$fandisk" --output-dir "$work/no_lines" $crest --strength-threshold 1e9 --rings 1 --quiet
check "--strength-threshold 1e9: exit status 0" [ "$rc" -eq 0 ]
check "--strength-threshold 1e9: no feature lines" \
  [ "$(json_int "$work/no_lines/summary.json" feature_lines total)" = 0 ]
check "--strength-threshold 1e9: empty polylines file" [ ! -s "$work/no_lines/feature_lines.polylines.txt" ]
check "--rings 1 recorded in summary" [ "$(json_get "$work/no_lines/summary.json" options rings)" = 1 ]

# alpha weighs the feature edges: a larger alpha cuts more of them. Measured on fandisk
# with the default solver: 1 patch at alpha 0.4, more than ten at 1.0; asserted: strictly
# more patches at 1.0 than at 0.4 (GAEC+KLj is a heuristic, so the direction of the
# change is what the method promises, not the counts).
run alpha_low "$fandisk" --output-dir "$work/alpha_low" $crest --alpha 0.4 --quiet
check "--alpha 0.4: exit status 0" [ "$rc" -eq 0 ]
run alpha_high "$fandisk" --output-dir "$work/alpha_high" $crest --alpha 1.0 --quiet
check "--alpha 1.0: exit status 0" [ "$rc" -eq 0 ]
patches_low="$(json_int "$work/alpha_low/summary.json" segmentation patches)"
patches_high="$(json_int "$work/alpha_high/summary.json" segmentation patches)"
check "--alpha 0.4 / 1.0: patches ${patches_low:-none} < ${patches_high:-none}" \
  [ "${patches_low:-0}" -ge 1 -a "${patches_high:-0}" -gt "${patches_low:-0}" ]
check "--alpha 1.0 recorded in summary" [ "$(json_number "$work/alpha_high/summary.json" options alpha)" = 1.0 ]
# One patch has no boundary: no curve, nothing split.
if [ "${patches_low:-0}" -eq 1 ]; then
  check "--alpha 0.4: one patch, no boundary curve" \
    [ "$(json_int "$work/alpha_low/summary.json" boundaries curves)" = 0 -a ! -s "$work/alpha_low/boundaries.polylines.txt" ]
  check "--alpha 0.4: one patch, the refined mesh is the mesh ($header_faces faces)" \
    [ "$(json_int "$work/alpha_low/summary.json" boundaries refined_faces)" = "$header_faces" ]
fi
# No smoothing: the curves as computed, so the same lengths before and after.
run unsmoothed "$fandisk" --output-dir "$work/unsmoothed" $crest --smoothing-iterations 0 --quiet
us="$work/unsmoothed/summary.json"
check "--smoothing-iterations 0: exit status 0 (stderr: $(tail -n 1 "$work/unsmoothed.err"))" [ "$rc" -eq 0 ]
check "--smoothing-iterations 0: recorded in options, no iteration run" \
  [ "$(json_int "$us" options smoothing_iterations)" = 0 -a "$(json_int "$us" boundaries smoothing_iterations)" = 0 ]
check "--smoothing-iterations 0: the same $curves curves" [ "$(json_int "$us" boundaries curves)" = "$curves" -a \
   "$(wc -l < "$work/unsmoothed/boundaries.polylines.txt")" -eq "${curves:-0}" ]
check "--smoothing-iterations 0: length before = after ($(json_number "$us" boundaries length_before))" \
  [ -n "$(json_number "$us" boundaries length_before)" -a \
   "$(json_number "$us" boundaries length_before)" = "$(json_number "$us" boundaries length_after)" -a \
   "$(json_number "$us" boundaries anisotropic_length_before)" = "$(json_number "$us" boundaries anisotropic_length_after)" ]
check "--smoothing-iterations 0: the lengths before are those of the smoothed run" \
  [ "$(json_number "$us" boundaries length_before)" = "$(json_number "$summary" boundaries length_before)" ]
check "--smoothing-iterations 0: the curves differ from the smoothed ones" \
  bash -c "! cmp -s '$work/unsmoothed/boundaries.polylines.txt' '$out/boundaries.polylines.txt'"
check "--smoothing-iterations 0: refined faces >= $header_faces" \
  [ "$(json_int "$us" boundaries refined_faces)" -ge "$header_faces" ]
run gamma "$fandisk" --output-dir "$work/gamma" $crest --gamma 0 --quiet
check "--gamma 0: exit status 0" [ "$rc" -eq 0 ]
check "--gamma 0 recorded in summary" [ "$(json_number "$work/gamma/summary.json" options gamma)" = 0.0 ]
for solver in gaec klj; do
  run "solver_$solver" "$fandisk" --output-dir "$work/solver_$solver" --solver "$solver" $crest --quiet
  check "--solver $solver: exit status 0 (stderr: $(tail -n 1 "$work/solver_$solver.err"))" [ "$rc" -eq 0 ]
  check "--solver $solver recorded in summary" [ "$(json_get "$work/solver_$solver/summary.json" options solver)" = "$solver" ]
  n="$(json_int "$work/solver_$solver/summary.json" segmentation patches)"
  check "--solver $solver: vertex ids cover [0, ${n:-none})" ids_cover "$work/solver_$solver/vertex_patches.txt" "${n:-0}"
done

# User feature lines: the first two edges of face 0 of fandisk, as one polyline.
first_face=$((4 + 3 * header_vertices)) # token index of face 0's vertex count
point() { echo "$(token $((4 + 3 * $1))) $(token $((5 + 3 * $1))) $(token $((6 + 3 * $1)))"; }
a="$(token $((first_face + 1)))"; b="$(token $((first_face + 2)))"; c="$(token $((first_face + 3)))"
echo "3 $(point "$a") $(point "$b") $(point "$c")" > "$work/user.polylines.txt"
run user "$fandisk" --output-dir "$work/user" --strength-threshold 1e9 --crease-angle 180 --feature-edges "$work/user.polylines.txt" --quiet
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
check "quad mesh: 8 lines in vertex_patches.txt" [ "$(wc -l < "$work/quad/vertex_patches.txt")" -eq 8 ]
check "quad mesh: 5 lines in face_patches.txt (one per quad)" [ "$(wc -l < "$work/quad/face_patches.txt")" -eq 5 ]
check "quad mesh: segmentation.ply has the 10 triangles" \
  ply_header_ok "$work/quad/segmentation.ply" 8 10

# ---- patch files in the file's order, through the repairs -------------------------------
# The box again, with a duplicate of point 2 (point 8, used by face 2 instead of 2), a
# point no face uses (point 9) and a duplicate of face 0 with the other orientation
# (face 5). The mesh has 8 vertices and 10 triangles; the patch files have the file's 10
# vertices and 6 faces. alpha 2 splits the box (measured: 2 patches).
cat > "$work/box_duplicates.off" <<'END_OF_MESH'
OFF
10 6 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
1 1 0
5 5 5
4 0 3 2 1
4 0 1 5 4
4 1 8 6 5
4 2 3 7 6
4 3 0 4 7
4 1 2 3 0
END_OF_MESH
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

# ---- the other formats -------------------------------------------------------------------
# fandisk as OBJ: same mesh, same feature lines as from the OFF file.
awk -v V="$header_vertices" '
  NR > 4 && NR <= 4 + 3 * V { c[(NR - 5) % 3] = $1; if ((NR - 4) % 3 == 0) print "v", c[0], c[1], c[2] }
  NR > 4 + 3 * V { if (k == 0) { k = $1; s = "f" } else { s = s " " ($1 + 1); if (--k == 0) print s } }
' "$work/fandisk.tokens" > "$work/fandisk.obj"
run obj "$work/fandisk.obj" --output-dir "$work/obj" $crest --quiet
check "fandisk.obj: exit status 0 (stderr: $(tail -n 1 "$work/obj.err"))" [ "$rc" -eq 0 ]
check "fandisk.obj: same vertex count as the OFF file" \
  [ "$(json_int "$work/obj/summary.json" mesh vertices)" = "$header_vertices" ]
check "fandisk.obj: same feature lines as the OFF file" \
  cmp -s "$work/obj/feature_lines.polylines.txt" "$out/feature_lines.polylines.txt"

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

# ---- the solve path: full graph, geodesic watershed -------------------------------------
# The default solves the reduced graph G' of the anisotropic watershed; --full-graph
# solves the vertex graph itself, so its nodes (reported as oversegments) are the
# vertices; --watershed geodesic changes the oversegmentation.
default_oversegments="$(json_int "$summary" segmentation oversegments)"
check "fandisk: oversegments in summary (${default_oversegments:-none}), fewer than the $v vertices" \
  [ "${default_oversegments:-0}" -ge 1 -a "${default_oversegments:-0}" -lt "$v" ]
run full_graph "$fandisk" --output-dir "$work/full_graph" --full-graph --crease-angle 180 --quiet
check "--full-graph: exit status 0 (stderr: $(tail -n 1 "$work/full_graph.err"))" [ "$rc" -eq 0 ]
check "--full-graph: cut cost in summary" [ -n "$(json_number "$work/full_graph/summary.json" segmentation cut_cost)" ]
check "--full-graph: one node per vertex (oversegments = $v)" \
  [ "$(json_int "$work/full_graph/summary.json" segmentation oversegments)" = "$v" ]
check "--full-graph recorded in summary" [ "$(json_get "$work/full_graph/summary.json" options full_graph)" = true ]
run geodesic "$fandisk" --output-dir "$work/geodesic" $crest --watershed geodesic --quiet
check "--watershed geodesic: exit status 0 (stderr: $(tail -n 1 "$work/geodesic.err"))" [ "$rc" -eq 0 ]
check "--watershed geodesic: cut cost in summary" \
  [ -n "$(json_number "$work/geodesic/summary.json" segmentation cut_cost)" ]
geodesic_oversegments="$(json_int "$work/geodesic/summary.json" segmentation oversegments)"
check "--watershed geodesic: oversegments (${geodesic_oversegments:-none}) in [1, $v)" \
  [ "${geodesic_oversegments:-0}" -ge 1 -a "${geodesic_oversegments:-0}" -lt "$v" ]
check "--watershed geodesic recorded in summary" [ "$(json_get "$work/geodesic/summary.json" options watershed)" = geodesic ]
run full_graph_watershed "$fandisk" --output-dir "$work/full_graph_watershed" --full-graph --watershed geodesic
check "--full-graph --watershed: a notice that the watershed has no effect" \
  [ "$rc" -eq 0 ] && grep -q '^notice: --full-graph: .*--watershed has no effect' "$work/full_graph_watershed.err"

# ---- edit scripts --------------------------------------------------------------------------
# fandisk, whose bounding box is [-0.46, 0.46] x [-0.26, 0.26] x [-0.5, 0.5]: a global
# refinement, a local one, a merge taken back by undo, then a sketch along the x = 0.4,
# y = 0.25 corner of the box (each point is moved onto the surface).
cat > "$work/edits.txt" <<'EOF'
# fandisk: global refine, local refine, merge, undo, sketch

alpha 1.0
refine ball 0 0 0 0.3  0.5     # the feature edges of the faces near the centre
merge  ball 0 0 0.3 0.25
undo
sketch 0.4 0.25 -0.4   0.4 0.25 0   0.4 0.25 0.4
EOF
run edits "$fandisk" --output-dir "$work/edits" $crest --edits "$work/edits.txt"
check "--edits: exit status 0 (stderr: $(tail -n 1 "$work/edits.err"))" [ "$rc" -eq 0 ]
es="$work/edits/summary.json"
# edit LINE KEY: the value of KEY in the summary's record of the edit on script line LINE.
edit() {
  python3 - "$es" "$1" "$2" <<'PY'
import json, sys
for e in json.load(open(sys.argv[1]))["edits"]:
    if e["line"] == int(sys.argv[2]) and sys.argv[3] in e: print(json.dumps(e[sys.argv[3]]))
PY
}
check "--edits: the five edits recorded in order (alpha refine merge undo sketch)" \
  [ "$(python3 -c 'import json, sys; print(" ".join("%d %s" % (e["line"], e["verb"]) for e in json.load(open(sys.argv[1]))["edits"]))' "$es")" = \
    "3 alpha 4 refine 5 merge 6 undo 7 sketch" ]
check "--edits: edits_file recorded in summary" [ "$(json_get "$es" options edits_file)" = "$work/edits.txt" ]
check "--edits: seconds.edits in summary" [ -n "$(json_get "$es" seconds edits)" ]
check "--edits: every edit has its seconds" \
  [ "$(python3 -c 'import json, sys; print(sum(isinstance(e.get("seconds"), float) for e in json.load(open(sys.argv[1]))["edits"]))' "$es")" -eq 5 ]
check "--edits: automatic_patches = patches of the run without edits ($patches)" \
  [ "$(json_int "$es" segmentation automatic_patches)" = "$patches" ]
# alpha 1.0 moves alpha_e to 1.0 on every feature edge and re-solves all of G': the
# weights and the solve of --alpha 1.0.
check "--edits: 'alpha 1.0' gives the patches of --alpha 1.0 ($(edit 3 patches) = ${patches_high:-none})" \
  [ "$(edit 3 patches)" = "$patches_high" ]
check "--edits: the ball of the refinement has faces ($(edit 4 faces))" [ "$(edit 4 faces)" -gt 0 ]
check "--edits: merge does not increase the patches ($(edit 5 patches) <= $(edit 4 patches))" \
  [ "$(edit 5 patches)" -le "$(edit 4 patches)" ]
check "--edits: undo takes back line 5" [ "$(edit 6 undone_line)" = 5 ]
check "--edits: undo restores the patches before the merge ($(edit 6 patches) = $(edit 4 patches))" \
  [ "$(edit 6 patches)" = "$(edit 4 patches)" ]
check "--edits: undo restores the cut cost before the merge ($(edit 6 cut_cost) = $(edit 4 cut_cost))" \
  [ "$(edit 6 cut_cost)" = "$(edit 4 cut_cost)" ]
check "--edits: the sketch has its 3 points" [ "$(edit 7 points)" = 3 ]
final_patches="$(json_int "$es" segmentation patches)"
check "--edits: segmentation.patches ($final_patches) = patches after the last edit ($(edit 7 patches))" \
  [ "$final_patches" = "$(edit 7 patches)" ]
# The patch files are the edited result. A face takes the patch covering most of its
# area under the smoothed boundaries, so a patch narrower than half a triangle (the
# sketch's) may own no face; the refined mesh, whose faces lie in exactly one patch,
# has every patch. A vertex on a crease takes the patch of its first face's side, so a
# patch one face wide between creases may have no vertex of its own.
check "--edits: the patch files are the edited result (face ids in [0, $final_patches))" \
  ids_in_range "$work/edits/face_patches.txt" "$final_patches"
check "--edits: the refined mesh has every patch of the edited result, [0, $final_patches)" \
  ids_cover <(awk -v nv="$(sed -n 's/^element vertex \([0-9]*\)$/\1/p' "$work/edits/segmentation_refined.ply")" \
                'p && ++row > nv { print $5 } /^end_header$/ { p = 1 }' "$work/edits/segmentation_refined.ply") \
            "$final_patches"
check "--edits: vertex ids in [0, $final_patches)" ids_in_range "$work/edits/vertex_patches.txt" "$final_patches"
check "--edits: a progress line per edit on stderr" [ "$(grep -c '^edit .*edits.txt:[0-9]*: ' "$work/edits.err")" -eq 5 ]
# A face of the file is all the triangles it became: the box's quads 0 and 4 are 4
# triangles; a region of only one patch's faces leaves a merge without effect.
printf 'refine faces 0 4  0.5\nmerge faces 2\nundo\nundo\n' > "$work/box_edits.txt"
run box_edits "$work/box.off" --output-dir "$work/box_edits" --edits "$work/box_edits.txt" --quiet
check "box --edits: exit status 0 (stderr: $(tail -n 1 "$work/box_edits.err"))" [ "$rc" -eq 0 ]
es="$work/box_edits/summary.json"
check "box --edits: 'faces 0 4' is 4 triangles" [ "$(edit 1 faces)" = 4 ]
check "box --edits: 'faces 2' is 2 triangles" [ "$(edit 2 faces)" = 2 ]
check "box --edits: the two undos take back lines 2 then 1" \
  [ "$(edit 3 undone_line) $(edit 4 undone_line)" = "2 1" ]
check "box --edits: back to the automatic patches after undoing everything" \
  [ "$(edit 4 patches)" = "$(json_int "$es" segmentation automatic_patches)" ]

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
# 65 alpha edits then 65 undos: the library keeps the last 64 edits, so the last undo
# (line 130) cannot take back line 1; 64 and 64 undo every edit.
{ for i in $(seq 1 65); do echo "alpha 0.$((6 + i % 2))"; done; for i in $(seq 1 65); do echo undo; done; } > "$bad/undo65.edits"
{ for i in $(seq 1 64); do echo "alpha 0.$((6 + i % 2))"; done; for i in $(seq 1 64); do echo undo; done; } > "$work/undo64.edits"
printf 'merge ball 0 0 0 -1\n' > "$bad/radius_negative.edits"
printf 'merge faces 0 12946\n' > "$bad/face_range.edits"
printf 'merge faces 0 -1\n' > "$bad/face_negative.edits"
printf 'merge sphere 0 0 0 1\n' > "$bad/region.edits"
printf 'scale faces 1 2 -1.5\n' > "$bad/factor.edits"
printf 'sketch 0 0 0 1 1\n' > "$bad/sketch_arity.edits"
printf 'sketch alpha 1 0 0 0 1 1 1\n' > "$bad/sketch_alpha.edits"
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

# Threads: the same outputs at 1, 2 and 8 threads as at the default (all cores).
for n in 1 2 8; do
  run "threads$n" "$fandisk" --output-dir "$work/threads$n" --threads "$n" $crest --quiet
  check "--threads $n: exit status 0" [ "$rc" -eq 0 ]
  check "--threads $n: the same face_patches.txt as the default run" \
    cmp -s "$work/threads$n/face_patches.txt" "$out/face_patches.txt"
  check "--threads $n: the same boundaries as the default run" \
    cmp -s "$work/threads$n/boundaries.polylines.txt" "$out/boundaries.polylines.txt"
done

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
expect_error edits_undo_history     1 'undo65\.edits:130: undo: cannot take back line 1: the segmentation keeps the last 64 edits only' "$fandisk" --edits "$bad/undo65.edits"
run undo64 "$fandisk" --output-dir "$work/undo64" $crest --edits "$work/undo64.edits" --quiet
check "64 edits and 64 undos: exit status 0 (stderr: $(tail -n 1 "$work/undo64.err"))" [ "$rc" -eq 0 ]
check "64 edits and 64 undos: the automatic patches ($(json_int "$work/undo64/summary.json" segmentation automatic_patches)) are back" \
  [ "$(json_int "$work/undo64/summary.json" segmentation patches)" = "$(json_int "$work/undo64/summary.json" segmentation automatic_patches)" ]
check "64 edits and 64 undos: the automatic segmentation's face patches are back" \
  cmp -s "$work/undo64/face_patches.txt" "$out/face_patches.txt"
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
expect_error edits_undo             1 'undo\.edits:3: undo: no edit to undo' "$fandisk" --edits "$bad/undo.edits"
expect_error edits_no_value         2 '--edits expects a value'     "$fandisk" --edits
expect_error watershed_unknown      2 "--watershed must be anisotropic or geodesic \(got 'foo'\)" "$fandisk" --watershed foo
expect_error full_graph_value       2 '--full-graph takes no value' "$fandisk" --full-graph=1
expect_error smoothing_negative     2 '--smoothing-iterations must be an integer >= 0' "$fandisk" --smoothing-iterations -1
expect_error smoothing_text         2 '--smoothing-iterations expects an integer' "$fandisk" --smoothing-iterations many

echo "script_program: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
