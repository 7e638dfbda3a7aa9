#!/usr/bin/env bash
# Every named parameter the package reads is documented in the manual's tables of named
# parameters, with its default, and every documented one is read: the package's own
# (declared in internal/parameters_interface.h, read as internal_np::TAG) against the
# first table, CGAL's (read as CGAL::internal_np::TAG, or through GetGeomTraits and
# GetVertexPointMap) against the second, named as CGAL's parameters_interface.h names them.
# Run by ctest with FS_SOURCE_DIR set.
set -euo pipefail
: "${FS_SOURCE_DIR:?FS_SOURCE_DIR must be set (the source folder)}"
python3 - "$FS_SOURCE_DIR" <<'PY'
import glob, os, re, sys

src = sys.argv[1]
inc = os.path.join(src, "include", "CGAL", "Feature_segmentation")
manual = open(os.path.join(src, "doc", "Feature_segmentation", "Feature_segmentation.txt")).read()
cgal_interface = "/usr/include/CGAL/STL_Extension/internal/parameters_interface.h"

# the package's tags: (tag, function name)
ours = dict(re.findall(r"FS_add_named_parameter\(\w+,\s*(\w+),\s*(\w+)\)",
                       open(os.path.join(inc, "internal", "parameters_interface.h")).read()))
cgal = dict(re.findall(r"CGAL_add_named_parameter\(\w+,\s*(\w+),\s*(\w+)\)", open(cgal_interface).read()))

code = ""
for path in glob.glob(os.path.join(inc, "**", "*.h"), recursive=True):
    if os.path.basename(path) not in ("parameters.h", "parameters_interface.h"):
        code += open(path).read()
read_ours, read_cgal = set(), set()
for prefix, tag in re.findall(r"(CGAL::)?internal_np::(\w+?)(?:_t)?\b", code):
    if tag in ours and not prefix:
        read_ours.add(ours[tag])
    elif tag in cgal:
        read_cgal.add(cgal[tag])
if "GetGeomTraits<" in code: read_cgal.add("geom_traits")
if "GetVertexPointMap<" in code: read_cgal.add("vertex_point_map")

def table(after):
    """The rows (name -> default) of the first table after the line starting with `after`."""
    i = manual.index(after)
    rows, started = {}, False
    for line in manual[i:].splitlines()[1:]:
        if line.startswith("|"):
            started = True
            cells = [c.strip() for c in line.strip("|").split("|")]
            m = re.fullmatch(r"`(\w+)`", cells[0])
            if m: rows[m.group(1)] = cells[2] if after.startswith("The package") else cells[1]
        elif started:
            break
    return rows

documented_ours = table("The package's named parameters")
documented_cgal = table("CGAL's named parameters that the package reads")
failed = 0
def check(what, ok, detail=""):
    global failed
    print(("ok   " if ok else "FAIL ") + what + (f" ({detail})" if detail and not ok else ""))
    failed += not ok

check(f"the package's {len(ours)} named parameters are all read", read_ours == set(ours.values()),
      "never read: " + ", ".join(sorted(set(ours.values()) - read_ours)))
check("every one is in the manual's table", set(ours.values()) <= set(documented_ours),
      "missing: " + ", ".join(sorted(set(ours.values()) - set(documented_ours))))
check("the table holds no other", set(documented_ours) <= set(ours.values()),
      "unknown: " + ", ".join(sorted(set(documented_ours) - set(ours.values()))))
check(f"CGAL's named parameters read ({', '.join(sorted(read_cgal))}) are those of the second table",
      read_cgal == set(documented_cgal), "read: " + ", ".join(sorted(read_cgal)) + "; documented: " +
      ", ".join(sorted(documented_cgal)))
empty = [n for n, d in {**documented_ours, **documented_cgal}.items() if not d]
check("every documented parameter has a default", not empty, ", ".join(empty))
sys.exit(1 if failed else 0)
PY
