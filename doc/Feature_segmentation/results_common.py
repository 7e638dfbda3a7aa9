# SPDX-License-Identifier: GPL-3.0-or-later
"""What the manual's table makers share (results_tables.py, results_quality.py): the
results folder (RESULTS, set by results_tables.py), the CSV and provenance readers, the
number formats and the Markdown table."""
import csv
import math
import os
import re
import sys

RESULTS = ""
ORGANIC = ("fertility", "botijo", "elk", "hand", "bunny")


def is_organic(model):
    return model.split("_")[0] in ORGANIC


class TableError(Exception):
    pass


def read_csv(name):
    path = os.path.join(RESULTS, name)
    if not os.path.exists(path):
        raise TableError(f"{path} is missing (run the benchmark that writes it; see "
                         f"benchmark/Feature_segmentation/results/README.md)")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def provenance(name):
    path = os.path.join(RESULTS, os.path.splitext(name)[0] + ".provenance.txt")
    if not os.path.exists(path):
        raise TableError(f"{path} is missing: every results CSV needs its provenance")
    fields = {}
    with open(path) as f:
        for line in f:
            key, _, value = line.partition(":")
            fields[key.strip()] = value.strip()
    for key in ("program", "machine", "date"):
        if not fields.get(key):
            raise TableError(f"{path}: no '{key}'")
    return fields


def source_line(name):
    p = provenance(name)
    arguments = (" " + p["arguments"]) if p.get("arguments") else ""
    return (f"<em>Measured on {p['date']}, {p['machine']}, by `{p['program']}{arguments}`; "
            f"source `benchmark/Feature_segmentation/results/{name}`.</em>")


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def fixed(text, digits=3):
    x = number(text)
    return "" if x is None else f"{x:.{digits}f}"


def count(text):
    x = number(text)
    return "" if x is None else f"{int(round(x)):,}"


def seconds(text):
    """Seconds with three significant digits at least, no more than three decimals."""
    x = number(text)
    if x is None:
        return ""
    return f"{x:.3f}" if x < 10 else f"{x:.2f}" if x < 100 else f"{x:.1f}"


def markdown(header, rows, align=None):
    align = align or ["---"] * len(header)
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def growth_exponent(points):
    """Least-squares slope of log y against log x."""
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx > 0 else None


# ---- Performance --------------------------------------------------------------------
