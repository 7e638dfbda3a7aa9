# Shared by the tests of the command-line program `feature_segmentation`
# (script_program.sh, script_program_inputs.sh), which source it: the program and the
# default model (checked to exist), a temporary work folder removed on exit, the pass and
# fail counters, the runner with its time limit, and the checks of the output files.
# Its name does not match script_*.sh: it is not a test of its own.
# Needs FS_BINARY_DIR (top build folder) and FS_MESH_DIR, as ctest sets them.

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

script_name="$(basename "$0" .sh)"
if [ ! -x "$program" ]; then
  echo "$script_name: the program is not built: $program" >&2
  exit 1
fi
if [ ! -f "$fandisk" ]; then
  echo "$script_name: the default model is missing: $fandisk" >&2
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

# write_box_off FILE: an open box of five unit squares (no top): 8 vertices, 5 quads ->
# 10 triangles.
write_box_off() {
  cat > "$1" <<'EOF'
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
}

# fandisk_ref KEY: a figure of fandisk at the defaults from data/fandisk.json, the one
# file the tests of every language read them from (nothing if absent: the check fails).
fandisk_ref() { json_get "$(dirname "${BASH_SOURCE[0]}")/data/fandisk.json" "$1"; }
