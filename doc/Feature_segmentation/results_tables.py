#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The manual's figure tables, made from the benchmarks' CSV files.

Usage: results_tables.py RESULTS_DIR MANUAL OUT_DIR

RESULTS_DIR is benchmark/Feature_segmentation/results: the CSV files that the
benchmark programs wrote, each with NAME.provenance.txt beside it (program,
arguments, machine, date; benchmark/Feature_segmentation/provenance.h). For every
table below this writes OUT_DIR/NAME.md, a Markdown table and its source line,
which the manual (MANUAL) includes with \\includedoc. So the figures of the manual's
Performance and Quality sections are the CSVs' own, and re-running a benchmark into
results/ updates the manual.

It also checks MANUAL: every table it includes exists, and the Performance and
Quality sections hold no table typed by hand. It exits with status 1 and one message
per problem otherwise.
"""

import csv
import math
import os
import re
import sys

import results_common
from results_common import *  # noqa: F401,F403 (the readers and formatters)
from results_quality import (quality_abc_dev, quality_cad, quality_coverage, quality_generated, quality_means,
                             quality_means_seeds, quality_nut, quality_resolution)


def perf_stages():
    name = "bench_segmentation.csv"
    rows = [r for r in read_csv(name) if r.get("status", "ok") in ("", "ok")]
    body = [[r["mesh"], count(r["faces"]), seconds(r["curvature_s"]), seconds(r["crest_lines_s"]),
             seconds(r["weights_s"]), seconds(r["solve_s"]), seconds(r["total_s"]), r["patches"],
             seconds(r["default_total_s"]), r["default_patches"]] for r in rows]
    return markdown(["mesh", "faces", "curvature", "crest lines", "weights", "solve (full graph)",
                     "total", "patches", "defaults: seconds", "defaults: patches"], body,
                    ["---"] + ["---:"] * 9) + "\n\n" + source_line(name)


def perf_fig8():
    name = "fig8.csv"
    rows = read_csv(name)
    body = []
    for r in rows:
        body.append([fixed(r["alpha"], 1), seconds(r["full_solve_s"]), fixed(r["full_cut_cost"], 2),
                     seconds(r["geodesic_overseg_s"]), seconds(r["geodesic_solve_s"]),
                     seconds(r["geodesic_total_s"]), fixed(r["geodesic_cut_cost"], 2),
                     seconds(r["anisotropic_overseg_s"]), seconds(r["anisotropic_solve_s"]),
                     seconds(r["anisotropic_total_s"]), fixed(r["anisotropic_cut_cost"], 2),
                     f"{100 * float(r['gap_anisotropic_vs_full']):.2f}%", r["anisotropic_vs_geodesic"]])
    table = markdown(["alpha", "(a) solve", "(a) cost", "(b) overseg", "(b) solve", "(b) total", "(b) cost",
                      "(c) overseg", "(c) solve", "(c) total", "(c) cost", "gap (c)-(a)", "(c) vs (b)"],
                     body, ["---:"] * 12 + [":---:"])
    totals = [float(r["anisotropic_total_s"]) for r in rows]
    gaps = [100 * float(r["gap_anisotropic_vs_full"]) for r in rows[1:]]
    lower = sum(1 for r in rows if r["anisotropic_vs_geodesic"] == "lower")
    summary = (f"On {rows[0]['mesh']} ({count(rows[0]['faces'])} faces): (c) takes at most {max(totals):.3f} s "
               f"at any alpha; above alpha {rows[0]['alpha']} it cuts lower than (a) by "
               f"{-max(gaps):.1f}% to {-min(gaps):.1f}%; it cuts lower than (b) at {lower} of the "
               f"{len(rows)} values.")
    return table + "\n\n" + summary + "\n\n" + source_line(name)


def editor_rows():
    rows = read_csv("bench_editor.csv")
    meshes = []
    for r in rows:
        if (r["mesh"], r["faces"]) not in meshes:
            meshes.append((r["mesh"], r["faces"]))
    return rows, meshes


def perf_editing_class():
    name = "bench_editor.csv"
    rows, meshes = editor_rows()
    ops = ["set_alpha", "add_to_alpha", "merge_patches", "add_sketch"]
    body = []
    for mesh, faces in meshes:
        cells = [mesh, count(faces)]
        found = False
        for op in ops:
            r = next((r for r in rows if r["mesh"] == mesh and r["edit"] == op + " (library)"), None)
            if r is None:
                cells.append("")
                continue
            found = True
            solve = number(r["solve_ms_median"])
            cells.append(f"{float(r['edit_ms_median']):.3g}" + (f" ({solve:.3g})" if solve is not None else ""))
        alpha = next((r for r in rows if r["mesh"] == mesh and r["edit"] == "set_alpha (library)"), None)
        cells.append(f"{float(alpha['labels_ms_median']):.3g}" if alpha else "")
        if found:
            body.append(cells)
    return markdown(["mesh", "faces", "`set_alpha()` (solve)", "`add_to_alpha()` (solve)", "`merge_patches()`",
                     "`add_sketch()` (solve)", "`vertex_patches()`"], body,
                    ["---"] + ["---:"] * 6) + "\n\n" + source_line(name)


def perf_editor_session():
    name = "bench_editor.csv"
    rows, meshes = editor_rows()
    ops = ["alpha", "refine", "coarsen", "merge", "undo", "redo", "sketch"]
    body = []
    for mesh, faces in meshes:
        session = {r["edit"]: r for r in rows if r["mesh"] == mesh and r["edit"] in ops}
        if not session:
            continue
        cells = [mesh, count(faces)]
        for op in ops:
            r = session.get(op)
            cells.append(f"{float(r['edit_ms_median']):.3g} ({float(r['edit_ms_max']):.3g})" if r else "")
        labels = [float(r["labels_ms_median"]) for r in session.values()]
        cells.append(f"{sorted(labels)[len(labels) // 2]:.3g}")
        body.append(cells)
    return markdown(["mesh", "faces"] + ops + ["labels"], body, ["---"] + ["---:"] * 9) + "\n\n" + source_line(name)


def perf_editor_page():
    name = "editor_page.csv"
    rows = read_csv(name)
    body = [[r["mesh"], count(r["faces"]), f"{float(r['server_ready_s']):.1f}", r["patches"],
             f"{float(r['load_ms']) / 1000:.1f}",
             f"{float(r['alpha_round_trip_ms_median']):.0f} ({float(r['alpha_round_trip_ms_max']):.0f})",
             f"{float(r['alpha_edit_request_ms_median']):.0f} ({float(r['alpha_server_ms_median']):.0f})",
             f"{float(r['alpha_draw_ms_median']):.0f}"]
            for r in rows]
    return markdown(["mesh", "faces", "server ready (s)", "patches", "page shown (s)",
                     "alpha round trip, ms", "edit request with labels (server), ms", "colours and redraw, ms"],
                    body, ["---"] + ["---:"] * 7) + "\n\n" + source_line(name)


def perf_scaling():
    name = "scaling.csv"
    rows = read_csv(name)
    most = max(int(r["threads"]) for r in rows)
    stages = ["load", "segmentation", "boundaries", "smoothing", "refinement", "write"]
    body = []
    for r in rows:
        if int(r["threads"]) != most:
            continue
        one = next((o for o in rows if o["mesh"] == r["mesh"] and int(o["threads"]) == 1), None)
        body.append([r["mesh"], count(r["faces"]), seconds(one["wall_s"]) if one else "", seconds(r["wall_s"]),
                     count(r["peak_mb"])] + [seconds(r[s + "_s"]) for s in stages] + [r["patches"]])
    table = markdown(["mesh", "faces", "wall s, 1 thread", f"wall s, {most} threads", "peak MB"] + stages +
                     ["patches"], body, ["---"] + ["---:"] * 11)
    series = [r for r in rows if r["mesh"].startswith("fandisk")]
    parts = []
    for threads in sorted({1, most}):
        pts = [(float(r["faces"]), float(r["wall_s"])) for r in series if int(r["threads"]) == threads]
        seg = [(float(r["faces"]), float(r["segmentation_s"])) for r in series if int(r["threads"]) == threads]
        e, s = growth_exponent(pts), growth_exponent(seg)
        if e is not None:
            parts.append(f"{threads} thread{'s' if threads > 1 else ''}: whole run {e:.2f}, segmentation {s:.2f}")
    exponents = ("Growth exponents over the fandisk series (the slope of log seconds against log faces; "
                 "1 is linear): " + "; ".join(parts) + ".") if parts else ""
    return (table + "\n\n" + exponents + "\n\n" + scaling_parts(series, most) + against_cgal(series, most) + "\n\n" +
            source_line(name))


def against_cgal(series, most):
    """The program against CGAL's read_polygon_mesh() and sharp_edges_segmentation() at 20
    degrees on the same file (the column cgal_sharp_edges_s, filled on one mesh)."""
    rows = [r for r in series if r.get("cgal_sharp_edges_s")]
    if not rows:
        return ""
    cgal = float(rows[0]["cgal_sharp_edges_s"])
    cells = []
    for r in sorted(rows, key=lambda r: int(r["threads"])):
        t = int(r["threads"])
        cells.append(f"{seconds(r['wall_s'])} s at {t} thread{'s' if t > 1 else ''} ({float(r['wall_s']) / cgal:.2f} times)")
    return (f"\n\nOn {rows[0]['mesh']} ({count(rows[0]['faces'])} faces), CGAL's `IO::read_polygon_mesh()` and "
            f"`Polygon_mesh_processing::sharp_edges_segmentation()` at 20 degrees take {seconds(str(cgal))} s "
            f"(in the benchmark's process); the program takes " + " and ".join(cells) + ".")


def scaling_parts(series, most):
    """The parts of the segmentation over the fandisk series: seconds at one thread and at
    every core, and the cost of each step (4 times the faces) at one thread."""
    parts = ["creases", "curvature", "feature_lines", "weight_terms", "oversegmentation"]
    if not series or any(p + "_s" not in series[0] for p in parts):
        return ""
    one = {int(r["faces"]): r for r in series if int(r["threads"]) == 1}
    many = {int(r["faces"]): r for r in series if int(r["threads"]) == most}
    body = []
    previous = None
    for faces in sorted(one):
        r, m = one[faces], many.get(faces)
        cells = [r["mesh"], count(faces)]
        for p in parts:
            cells.append(seconds(r[p + "_s"]) + (" / " + seconds(m[p + "_s"]) if m and most > 1 else ""))
        if previous is not None:
            cells += [f"{float(r['wall_s']) / float(previous['wall_s']):.2f}",
                      f"{float(r['curvature_s']) / float(previous['curvature_s']):.2f}"]
        else:
            cells += ["", ""]
        if m and most > 1:
            cells.append(f"{float(m['wall_s']) / float(r['wall_s']):.2f}")
        body.append(cells)
        previous = r
    threads = f" / {most} threads" if most > 1 else ""
    header = ["mesh", "faces"] + [p.replace("_", " ") + ", s (1 thread" + threads + ")" for p in parts] + \
             ["wall, x of the mesh 4 times smaller", "curvature, x of the mesh 4 times smaller"]
    if most > 1:
        header.append(f"wall, {most} threads / 1")
    return ("The parts of the stage segmentation, and the cost of 4 times the faces (one thread; linear: "
            "4.0):\n\n" + markdown(header, body, ["---"] + ["---:"] * (len(header) - 1)))


def perf_mesh_input():
    name = "mesh_input.csv"
    rows = read_csv(name)
    labels = {"off": "OFF", "obj": "OBJ (`f a//n`)", "ply": "binary PLY", "stl": "binary STL"}
    body = [[labels.get(r["format"], r["format"]), count(r["faces"]), f"{float(r['bytes']) / 1e6:.1f}",
             seconds(r["load"]), seconds(r["parse"]), seconds(r["cgal_read_polygon_soup"]),
             seconds(r["count_lines"])] for r in rows]
    return markdown(["format", "faces", "MB", "load (the program's reader)", "parse only",
                     "CGAL `read_polygon_soup()`", "count the lines"], body,
                    ["---"] + ["---:"] * 6) + "\n\n" + source_line(name)


def perf_batch():
    name = "batch.csv"
    rows = read_csv(name)
    body = [["`feature_segmentation batch`" if r["runner"] == "program batch" else "Dask, local cluster",
             r["workers"], r["meshes"], count(r["faces"]), f"{float(r['seconds']):.1f}",
             count(f"{float(r['meshes_per_minute']):.0f}"), count(f"{float(r['faces_per_second']):.0f}")]
            for r in rows]
    return markdown(["runner", "workers", "meshes", "faces", "seconds", "meshes per minute", "faces per second"],
                    body, ["---"] + ["---:"] * 6) + "\n\n" + source_line(name)


# ---- Quality ------------------------------------------------------------------------

TABLES = {
    "perf_stages": perf_stages,
    "perf_fig8": perf_fig8,
    "perf_editing_class": perf_editing_class,
    "perf_editor_session": perf_editor_session,
    "perf_editor_page": perf_editor_page,
    "perf_scaling": perf_scaling,
    "perf_mesh_input": perf_mesh_input,
    "perf_batch": perf_batch,
    "quality_nut": quality_nut,
    "quality_coverage": quality_coverage,
    "quality_resolution": quality_resolution,
    "quality_cad": quality_cad,
    "quality_abc_dev": quality_abc_dev,
    "quality_generated": quality_generated,
    "quality_means": quality_means,
    "quality_means_seeds": quality_means_seeds,
}


def check_manual(manual):
    problems = []
    with open(manual) as f:
        text = f.read()
    included = set(re.findall(r"\\includedoc\s+(\S+)\.md", text))
    for name in sorted(included - set(TABLES)):
        problems.append(f"{manual}: \\includedoc {name}.md, but results_tables.py makes no such table")
    for name in sorted(set(TABLES) - included):
        problems.append(f"{manual}: the table {name} is made but not included")
    for section in ("fs_performance", "fs_quality"):
        m = re.search(r"^\\section " + section + r"\b(.*?)(?=^\\section |\Z)", text, re.S | re.M)
        if not m:
            problems.append(f"{manual}: no section {section}")
            continue
        start = text[:m.start()].count("\n") + 1
        for k, line in enumerate(m.group(0).splitlines()):
            if line.startswith("|"):
                problems.append(f"{manual}:{start + k}: a table typed by hand in {section}; its figures belong "
                                f"in a results CSV and a table of results_tables.py")
                break
    return problems


def main(argv):
    if len(argv) != 4:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    results_common.RESULTS, manual, out = argv[1:]
    os.makedirs(out, exist_ok=True)
    problems = []
    for name, make in TABLES.items():
        try:
            text = make()
        except (TableError, KeyError, ValueError) as e:
            problems.append(f"table {name}: {type(e).__name__}: {e}")
            continue
        with open(os.path.join(out, name + ".md"), "w") as f:
            f.write(text + "\n")
    problems += check_manual(manual)
    for p in problems:
        print("results_tables.py: " + p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
