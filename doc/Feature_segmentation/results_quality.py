# SPDX-License-Identifier: GPL-3.0-or-later
"""The Quality section's tables of the manual (results_tables.py makes them all): the hex
nut, the coverage of the paper's models, the resolution series, and the CAD, ABC and
generated parts with their means."""
from results_common import *  # noqa: F401,F403 (the readers and formatters)


def quality_nut():
    name = "quality_table.csv"
    rows = [r for r in read_csv(name) if r["model"] == "abc_00000006"]
    if not rows:
        raise TableError(f"{name}: no rows of abc_00000006")
    body = []
    for r in rows:
        setting = r["setting"] + (", smoothed" if r["smoothed"] == "1" else "") + f" ({r['role']})"
        body.append([r["method"], setting, r["patches"], fixed(r["precision"]), fixed(r["recall"]),
                     fixed(r["f_score"]), fixed(r["rand_index"]), r["over_segmentation"], r["under_segmentation"],
                     fixed(r["sharp_curve_recall"]), fixed(r["cut_cost"], 2), fixed(r["curve_f_score"])])
    return markdown(["method", "setting", "patches", "boundary P", "boundary R", "boundary F", "Rand index", "over",
                     "under", "sharp-curve recall", "cut cost", "curve F"], body) + "\n\n" + source_line(name)


def quality_coverage():
    name = "quality_table.csv"
    rows = read_csv(name)
    groups = []
    for r in rows:
        key = (r["method"], r["role"], r["smoothed"])
        if key not in groups:
            groups.append(key)
    body = []
    for method, role, smoothed in groups:
        sel = [r for r in rows if (r["method"], r["role"], r["smoothed"]) == (method, role, smoothed)]

        def mean(field, keep):
            xs = [number(r[field]) for r in sel if keep(r) and number(r[field]) is not None]
            return (sum(xs) / len(xs), len(xs)) if xs else (None, 0)

        def cell(field, keep, curve_field=None):
            m, n = mean(field, keep)
            text = "" if m is None else f"{m:.3f}"
            if curve_field and smoothed == "1":
                c, _ = mean(curve_field, keep)
                text += "" if c is None else f" ({c:.3f})"
            return text + f" ({n} model{'' if n == 1 else 's'})" if m is not None and n != expected(keep) else text

        def expected(keep):
            return len({r["model"] for r in rows if keep(r)})

        cad = lambda r: not is_organic(r["model"])
        organic = lambda r: is_organic(r["model"])
        every = lambda r: True
        patches = sorted(int(r["patches"]) for r in sel if number(r["patches"]) is not None)
        median = patches[len(patches) // 2] if patches else ""
        body.append([method, role + (", smoothed" if smoothed == "1" else ""),
                     cell("coverage", cad, "curve_coverage"), cell("coverage", organic, "curve_coverage"),
                     cell("redundancy_fraction", every, "curve_redundancy_fraction"), f"{median:,}" if median != "" else ""])
    models = sorted({r["model"] for r in rows})
    cad_count = sum(1 for m in models if not is_organic(m))
    return markdown(["method", "setting", f"mean coverage, {cad_count} CAD-like models",
                     f"mean coverage, {len(models) - cad_count} organic models",
                     f"mean redundancy, all {len(models)}", "median patches"], body) + "\n\n" + source_line(name)


def quality_resolution():
    name = "resolution.csv"
    rows = read_csv(name)
    body = [[r["subdivisions"], count(r["faces"]), r["patches"], fixed(r["precision"]), fixed(r["recall"]),
             fixed(r["f"]), seconds(r["seconds"])] for r in rows]
    return markdown(["subdivisions", "faces", "patches", "boundary P", "boundary R",
                     "boundary F against the coarsest", "seconds"], body,
                    ["---:"] * 7) + "\n\n" + source_line(name)


CAD_METHODS = [("default", "default"), ("paper", "paper's pipeline"), ("sharp20", "sharp edges 20"),
               ("sharp45", "45"), ("sharp60", "60"), ("ransac", "Efficient RANSAC"), ("vsa", "VSA (true count)")]


def cad_rows():
    name = "cad_parts.csv"
    return name, read_csv(name)


def quality_parts(set_name, label, noisy=()):
    """The clean scores of the parts of `set_name`, then the defaults' at each noise level of `noisy`."""
    name, rows = cad_rows()
    parts = []
    for r in rows:
        if r["set"] == set_name and number(r["noise"]) == 0 and r["part"] not in [p["part"] for p in parts]:
            parts.append(r)
    if not parts:
        raise TableError(f"{name}: no clean rows of the set {set_name}")

    def row(part, level, method, set_=set_name):
        return next((r for r in rows if r["set"] == set_ and r["part"] == part and number(r["noise"]) == level
                     and r["method"] == method), None)

    body = []
    for p in parts:
        cells = [label(p["part"]), count(p["faces"]), p["true_patches"], fixed(p["tangent_share"]),
                 fixed(p["band_share"])]
        for method, _ in CAD_METHODS:
            r = row(p["part"], 0, method)
            cells.append(f"{fixed(r['f'])} ({r['patches']})" if r else "")
        for level in noisy:
            r = row(p["part"], level, "default")
            cells.append(f"{fixed(r['f'])} ({r['patches']}/{r['small_patches']})" if r else "")
        body.append(cells)
    mean = [f"mean of the {len(parts)} parts", "", "", "", ""]
    for level, methods in [(0, [m for m, _ in CAD_METHODS])] + [(level, ["default"]) for level in noisy]:
        for method in methods:
            r = row("", level, method, "mean " + set_name)
            mean.append(f"**{fixed(r['f'])}**" if r else "")
    body.append(mean)
    header = ["part", "faces", "true patches", "tang.", "band"] + [m[1] for m in CAD_METHODS]
    header += [f"default, {100 * level:g}% noise (patches/small)" for level in noisy]
    return markdown(header, body, ["---", "---:", "---:", "---:", "---:"] + ["---:"] * (len(header) - 5)) + \
        "\n\n" + source_line(name)


def quality_cad():
    return quality_parts("cad", lambda part: part.split("_")[0])


def quality_abc_dev():
    return quality_parts("abc-dev", lambda part: part.replace("abc_", ""))


def quality_generated():
    def label(part):
        kind, _, resolution = part.rpartition("_")
        return kind.replace("_", " ") + "&nbsp;" + resolution
    return quality_parts("generated", label, (0.001, 0.003))


def quality_means(name="cad_parts.csv", nut_line=True):
    """The mean boundary F of every set and method at every noise level of `name`, the mean
    Rand index likewise, and the hex nut."""
    rows = read_csv(name)
    sets = []
    for r in rows:
        if r["set"].startswith("mean ") and r["set"] not in sets:
            sets.append(r["set"])
    levels = sorted({number(r["noise"]) for r in rows if r["set"].startswith("mean ")})

    def table(column):
        body = []
        for s in sets:
            for level in levels:
                cells = [s[len("mean "):], f"{100 * level:g}%" if level else "0"]
                any_value = False
                for method, _ in CAD_METHODS:
                    r = next((r for r in rows
                              if r["set"] == s and number(r["noise"]) == level and r["method"] == method), None)
                    cells.append(fixed(r[column]) if r else "")
                    any_value |= r is not None
                if any_value:
                    body.append(cells)
        return markdown(["set", "noise (of the diagonal)"] + [m[1] for m in CAD_METHODS], body,
                        ["---", "---:"] + ["---:"] * len(CAD_METHODS))

    text = "Boundary F:\n\n" + table("f") + "\n\nRand index (faces weighted by area):\n\n" + table("rand_index")
    nut = [r for r in rows if r["set"] == "abc" and number(r["noise"]) == 0] if nut_line else []
    if nut:
        names = dict(CAD_METHODS, sharp45="sharp edges 45", sharp60="sharp edges 60")
        cells = [f"{names.get(r['method'], r['method'])} {fixed(r['f'])} ({r['patches']})" for r in nut]
        text += (f"\n\nThe hex nut (ABC 00000006, {count(nut[0]['faces'])} faces, {nut[0]['true_patches']} true "
                 f"patches), clean: " + ", ".join(cells) + ".")
    return text + "\n\n" + source_line(name)


def quality_means_seeds():
    """The means of quality_means() over three noise realisations (evaluate_quality --noise-seeds 3)."""
    return quality_means("cad_parts_3_seeds.csv", nut_line=False)
