#!/usr/bin/env bash
# Tests the command-line program `feature_segmentation` on fandisk: a run whose outputs
# (feature lines, segmentation, boundaries, summary) must be complete, well-formed,
# consistent with the mesh and deterministic, the options of the detection, the
# segmentation and the smoothing, the same mesh as OBJ, the solve paths (full graph,
# geodesic watershed), edit scripts, and the same outputs at any number of threads.
# Quads, repairs, the other formats and every kind of bad input and bad option are in
# script_program_inputs.sh; the shared setup and checks in program_common.sh.
# Run by ctest with FS_BINARY_DIR (top build folder) and FS_MESH_DIR set.
set -uo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/program_common.sh"

# ---- fandisk with its crest lines ------------------------------------------------------
# At the defaults a clean CAD tessellation such as fandisk is cut along its creases and
# curvature discontinuities and gets no crest lines (checked below, "the default run");
# the runs that check feature lines, curves and smoothing ask for the paper's crest lines
# too, with --crest-lines-on-clean-tessellations ($crest).
crest=--crest-lines-on-clean-tessellations
out="$work/fandisk"
run fandisk "$fandisk" --output-dir "$out" $crest
check "fandisk: exit status 0 (got $rc; stderr: $(tail -n 1 "$work/fandisk.err"))" [ "$rc" -eq 0 ]
for f in feature_lines.polylines.txt feature_lines.types.txt feature_lines.obj summary.json segmentation.ply \
         face_patches.txt vertex_patches.txt boundaries.polylines.txt boundaries.types.txt segmentation_refined.ply; do
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
# the peak resident memory of each stage (Linux): at least the program's own pages and
# the mesh, so more than 1 MiB
if [ -r /proc/self/status ]; then
  for stage in load segmentation write; do
    peak="$(json_get "$summary" peak_memory_mib $stage)"
    check "fandisk: peak_memory_mib.$stage ($peak) above 1 MiB" \
      python3 -c "import sys; sys.exit(0 if float('${peak:-0}') > 1 else 1)"
  done
fi
# feature_lines.*: the crest lines, then the creases and seams chained from the crease
# edges, each typed in feature_lines.types.txt and as an object of the OBJ file
crease_lines="$(json_int "$summary" feature_lines creases)"
seam_lines="$(json_int "$summary" feature_lines seams)"
all_lines=$((total + crease_lines + seam_lines))
lines="$(wc -l < "$out/feature_lines.polylines.txt")"
check "fandisk: polylines lines ($lines) = crest lines + creases + seams in summary ($all_lines)" [ "$lines" -eq "$all_lines" ]
check "fandisk: crease lines written (${crease_lines:-none})" [ "${crease_lines:-0}" -gt 0 ]
check "fandisk: feature_lines.types.txt: a type per polyline" [ "$(wc -l < "$out/feature_lines.types.txt")" -eq "$lines" ]
for t in ridge:$ridges valley:$valleys crease:$crease_lines seam:$seam_lines; do
  check "fandisk: ${t#*:} polylines typed ${t%%:*}" [ "$(grep -cx "${t%%:*}" "$out/feature_lines.types.txt")" -eq "${t#*:}" ]
done
check "fandisk: feature_lines.obj: one object per type (crease, seam, ridge, valley)" \
  [ "$(grep '^o ' "$out/feature_lines.obj" | tr '\n' ' ')" = "o crease o seam o ridge o valley " ]
check "fandisk: polylines file well-formed" polylines_well_formed "$out/feature_lines.polylines.txt"
obj_lines="$(grep -c '^l ' "$out/feature_lines.obj")"
obj_vertices="$(grep -c '^v ' "$out/feature_lines.obj")"
poly_points="$(awk '{ s += $1 } END { print s + 0 }' "$out/feature_lines.polylines.txt")"
closed="$(awk '{ if ($2 == $(NF - 2) && $3 == $(NF - 1) && $4 == $NF) c++ } END { print c + 0 }' "$out/feature_lines.polylines.txt")"
check "fandisk: OBJ l records ($obj_lines) = polylines ($all_lines)" [ "$obj_lines" -eq "$all_lines" ]
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
# The patch count is that of the faces. Vertex labels are the clustering's; a face takes
# the majority of its vertices' patches, so a patch of a few scattered vertices may own
# no face: every face id is a vertex id, and the faces hold exactly $patches of them.
check "fandisk: face ids: $patches distinct" [ "$(sort -u "$out/face_patches.txt" | wc -l)" -eq "${patches:-0}" ]
check "fandisk: every face id is a vertex id" \
  bash -c "[ -z \"\$(comm -23 <(sort -u '$out/face_patches.txt') <(sort -u '$out/vertex_patches.txt'))\" ]"
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
crease_curves="$(json_int "$summary" boundaries crease_curves)"
check "fandisk: boundaries.polylines.txt has one line per curve ($curves inside faces, ${crease_curves:-none} on creases)" \
  [ "$(wc -l < "$out/boundaries.polylines.txt")" -eq "$((curves + crease_curves))" ]
check "fandisk: boundaries.types.txt: $curves smoothed, $crease_curves crease" \
  [ "$(grep -cx smoothed "$out/boundaries.types.txt")" -eq "$curves" -a \
    "$(grep -cx crease "$out/boundaries.types.txt")" -eq "$crease_curves" ]
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
# A clean CAD tessellation: its crease edges are its sharp creases and the seams of its
# blends (curvature discontinuities, as test_tangent_discontinuities finds), and its crest
# lines weigh less (alpha - 0.5); the boundaries run along the creases and seams but one,
# which crosses the curved side along a crest line and is smoothed, and the patches are
# the regions they bound (every one owns faces). The feature files hold the creases and
# seams as polylines of those edges, and the crest lines; the boundary file the creases
# between two patches and the smoothed curve. The figures: data/fandisk.json.
crease_edges="$(fandisk_ref crease_edges)"
seam_edges="$(fandisk_ref seam_edges)"
crest_lines="$(fandisk_ref crest_lines)"
seam_lines="$(fandisk_ref seam_lines)"
fandisk_patches="$(fandisk_ref patches)"
run default "$fandisk" --output-dir "$work/default" --quiet
ds="$work/default/summary.json"
check "default: exit status 0 (stderr: $(tail -n 1 "$work/default.err"))" [ "$rc" -eq 0 ]
# the feature lines are the crest lines and the seam lines through the faces, each typed
check "default: $crest_lines crest lines on a clean tessellation, typed ridge or valley" \
  [ "$(grep -c -x -e ridge -e valley "$work/default/feature_lines.types.txt")" = "$crest_lines" ]
check "default: the feature lines ($(json_int "$ds" feature_lines total)) are the crest lines and $seam_lines seam lines, typed seam_line" \
  [ "$(json_int "$ds" feature_lines total)" = "$((crest_lines + seam_lines))" -a \
    "$(json_int "$ds" feature_lines seam_lines)" = "$seam_lines" -a \
    "$(grep -c -x seam_line "$work/default/feature_lines.types.txt")" = "$seam_lines" ]
# a polyline of n points covers n - 1 edges
check "default: the crease and seam polylines cover the $crease_edges crease edges" \
  [ "$(paste -d' ' "$work/default/feature_lines.types.txt" "$work/default/feature_lines.polylines.txt" |
       awk '$1 == "crease" || $1 == "seam" { s += $2 - 1 } END { print s }')" = "$crease_edges" ]
check "default: the seams are the $seam_edges edges of the blends' tangent lines" \
  [ "$(paste -d' ' "$work/default/feature_lines.types.txt" "$work/default/feature_lines.polylines.txt" |
       awk '$1 == "seam" { s += $2 - 1 } END { print s + 0 }')" = "$seam_edges" ]
check "default: $crease_edges crease edges, and the crest lines' edges" \
  [ "$(json_int "$ds" "" crease_edges)" = "$crease_edges" -a "$(json_int "$ds" "" feature_edges)" -gt "$crease_edges" ]
check "default: $fandisk_patches patches ($(json_int "$ds" segmentation patches))" \
  [ "$(json_int "$ds" segmentation patches)" = "$fandisk_patches" ]
check "default: one boundary curve inside faces (smoothed), the others on creases" \
  [ "$(json_int "$ds" boundaries curves)" = 1 -a "$(json_int "$ds" boundaries crease_curves)" -gt 0 -a \
    "$(grep -c -x smoothed "$work/default/boundaries.types.txt")" = 1 -a \
    "$(grep -v -x -c -e crease -e smoothed "$work/default/boundaries.types.txt")" = 0 ]
check "default: the crease boundaries are polylines of crease edges (at most $crease_edges)" \
  [ "$(paste -d' ' "$work/default/boundaries.types.txt" "$work/default/boundaries.polylines.txt" |
       awk '$1 == "crease" { s += $2 - 1 } END { print s }')" -le "$crease_edges" ]
check "default: face ids cover exactly [0, $fandisk_patches)" ids_cover "$work/default/face_patches.txt" "$fandisk_patches"
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
check "--strength-threshold 1e9: only creases and seams in the polylines file" \
  [ -z "$(grep -v -x -e crease -e seam "$work/no_lines/feature_lines.types.txt")" ]
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
    [ "$(json_int "$work/alpha_low/summary.json" boundaries curves)" = 0 -a ! -s "$work/alpha_low/boundaries.polylines.txt" -a \
      "$(json_int "$work/alpha_low/summary.json" boundaries crease_curves)" = 0 ]
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
   "$(grep -cx smoothed "$work/unsmoothed/boundaries.types.txt")" -eq "${curves:-0}" ]
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
check "--help: fits a screen ($(wc -l < "$work/help.out") lines <= 60), every option named" \
  bash -c "[ \$(wc -l < '$work/help.out') -le 60 ] && grep -q -- '--alpha X' '$work/help.out' && grep -q -- '--help-all' '$work/help.out'"
run help_all --help-all
help_all_ok() { [ "$rc" -eq 0 ] && grep -q '^Edit scripts' "$work/help_all.out"; }
check "--help-all: exit status 0, the edit scripts explained" help_all_ok
# a misspelt subcommand is named as such, not taken for a second mesh
run misspelt edti "$fandisk"
misspelt_ok() { [ "$rc" -eq 2 ] && grep -q "^error: unknown subcommand 'edti'" "$work/misspelt.err"; }
check "edti: exit status 2, 'unknown subcommand' ($(cat "$work/misspelt.err"))" misspelt_ok

# ---- fandisk as OBJ (STL and PLY: script_program_inputs.sh) ------------------------------
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
check "--edits: the edit script recorded in the summary's options" [ "$(json_get "$es" options edits)" = "$work/edits.txt" ]
check "--edits: seconds.edits in summary" [ -n "$(json_get "$es" seconds edits)" ]
check "--edits: every edit has its seconds" \
  [ "$(python3 -c 'import json, sys; print(sum(isinstance(e.get("seconds"), float) for e in json.load(open(sys.argv[1]))["edits"]))' "$es")" -eq 5 ]
check "--edits: automatic_patches = patches of the run without edits ($patches)" \
  [ "$(json_int "$es" segmentation automatic_patches)" = "$patches" ]
# alpha 1.0 moves alpha_e to 1.0 on every feature edge and re-solves all of G': the
# weights and the solve of --alpha 1.0 (both counted before the smoothing: the faces'
# patches by the majority of their vertices).
automatic_high="$(json_int "$work/alpha_high/summary.json" segmentation automatic_patches)"
check "--edits: 'alpha 1.0' gives the patches of --alpha 1.0 ($(edit 3 patches) = ${automatic_high:-none})" \
  [ "$(edit 3 patches)" = "$automatic_high" ]
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
# The patch files are the edited result. A face takes the patch covering most of its
# area under the smoothed boundaries, so a patch narrower than half a triangle (the
# sketch's) may own no face; the count of the summary is that of the faces. The refined
# mesh, whose faces lie in exactly one patch, has every patch. A vertex on a crease takes
# the patch of its first face's side, so a patch one face wide between creases may have
# no vertex of its own.
check "--edits: segmentation.patches ($final_patches) = the patches of face_patches.txt" \
  [ "$final_patches" = "$(sort -u "$work/edits/face_patches.txt" | wc -l)" ]
awk -v nv="$(sed -n 's/^element vertex \([0-9]*\)$/\1/p' "$work/edits/segmentation_refined.ply")" \
    'p && ++row > nv { print $5 } /^end_header$/ { p = 1 }' "$work/edits/segmentation_refined.ply" | sort -u > "$work/refined_ids"
sort -u "$work/edits/face_patches.txt" > "$work/face_ids"
sort -u "$work/edits/vertex_patches.txt" > "$work/vertex_ids"
check "--edits: the refined mesh has every patch of the faces" [ -z "$(comm -23 "$work/face_ids" "$work/refined_ids")" ]
check "--edits: every vertex id is a patch of the refined mesh" [ -z "$(comm -23 "$work/vertex_ids" "$work/refined_ids")" ]
check "--edits: a progress line per edit on stderr" [ "$(grep -c '^edit .*edits.txt:[0-9]*: ' "$work/edits.err")" -eq 5 ]
# A face of the file is all the triangles it became: the box's quads 0 and 4 are 4
# triangles; a region of only one patch's faces leaves a merge without effect.
write_box_off "$work/box.off"
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

# 65 alpha edits then 65 undos: 65 earlier states of fandisk (8 bytes per edge and
# per vertex each) fit in the default 256 MiB, so they undo every edit (with --undo-memory 0 the
# second undo fails: script_program_inputs.sh).
{ for i in $(seq 1 65); do echo "alpha 0.$((6 + i % 2))"; done; for i in $(seq 1 65); do echo undo; done; } > "$work/undo64.edits"
run undo64 "$fandisk" --output-dir "$work/undo64" $crest --edits "$work/undo64.edits" --quiet
check "65 edits and 65 undos: exit status 0 (stderr: $(tail -n 1 "$work/undo64.err"))" [ "$rc" -eq 0 ]
check "65 edits and 65 undos: the automatic patches ($(json_int "$work/undo64/summary.json" segmentation automatic_patches)) are back" \
  [ "$(json_int "$work/undo64/summary.json" segmentation patches)" = "$(json_int "$work/undo64/summary.json" segmentation automatic_patches)" ]
check "65 edits and 65 undos: the automatic segmentation's face patches are back" \
  cmp -s "$work/undo64/face_patches.txt" "$out/face_patches.txt"

# Threads: the same outputs at 1, 2 and 8 threads as at the default (all cores).
for n in 1 2 8; do
  run "threads$n" "$fandisk" --output-dir "$work/threads$n" --threads "$n" $crest --quiet
  check "--threads $n: exit status 0" [ "$rc" -eq 0 ]
  for f in face_patches.txt vertex_patches.txt segmentation.ply segmentation_refined.ply \
           feature_lines.polylines.txt feature_lines.types.txt feature_lines.obj \
           boundaries.polylines.txt boundaries.types.txt; do
    check "--threads $n: the same $f as the default run" cmp -s "$work/threads$n/$f" "$out/$f"
  done
done

echo "script_program: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
