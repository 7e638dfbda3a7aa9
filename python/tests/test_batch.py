# SPDX-License-Identifier: GPL-3.0-or-later
"""Batch runs: `feature_segmentation batch` and the Dask runner (a local cluster of 2
worker processes) on 24 meshes (CGAL's demo meshes and generated boxes and
cylinders) and a bad file give the same table; both resume."""
import csv
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from feature_segmentation import batch

MESHES = os.environ["FS_MESH_DIR"]
PROGRAM = os.path.join(os.environ["FS_BINARY_DIR"], "demo/Feature_segmentation/feature_segmentation")
DEMO = ["anchor_dense.off", "couplingdown.off", "cube.off", "cube_quad.off", "fandisk.off", "pinion.off",
        "rotor.off", "sphere.off"]


def write_off(path, vertices, faces):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for p in vertices:
            out.write(f"{p[0]!r} {p[1]!r} {p[2]!r}\n")
        for f in faces:
            out.write("3 " + " ".join(str(int(i)) for i in f) + "\n")


def box(n, size):
    """A box of size[0] x size[1] x size[2], each face an n x n grid of quads split in two."""
    vertices, faces, index = [], [], {}

    def vertex(p):
        key = tuple(np.round(p, 9))
        if key not in index:
            index[key] = len(vertices)
            vertices.append(p)
        return index[key]

    for axis in range(3):
        for side in (0, 1):
            u, w = (axis + 1) % 3, (axis + 2) % 3
            grid = {}
            for i in range(n + 1):
                for j in range(n + 1):
                    p = np.zeros(3)
                    p[axis], p[u], p[w] = side * size[axis], i / n * size[u], j / n * size[w]
                    grid[i, j] = vertex(p)
            for i in range(n):
                for j in range(n):
                    a, b, c, d = grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]
                    faces += [[a, b, c], [a, c, d]] if side == 1 else [[a, c, b], [a, d, c]]
    return np.array(vertices), np.array(faces)


def cylinder(k, h, rows):
    """A closed cylinder of radius 1 with k sides and a fan at each end."""
    vertices = [[np.cos(2 * np.pi * i / k), np.sin(2 * np.pi * i / k), r * h / rows]
                for r in range(rows + 1) for i in range(k)]
    vertices += [[0, 0, 0], [0, 0, h]]
    faces = []
    for r in range(rows):
        for i in range(k):
            a, b = r * k + i, r * k + (i + 1) % k
            faces += [[a, b, b + k], [a, b + k, a + k]]
    bottom, top = len(vertices) - 2, len(vertices) - 1
    for i in range(k):
        faces += [[bottom, (i + 1) % k, i], [top, rows * k + i, rows * k + (i + 1) % k]]
    return np.array(vertices), np.array(faces)


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("meshes")
    for name in DEMO:
        shutil.copy(os.path.join(MESHES, name), folder / name)
    for i in range(8):
        write_off(folder / f"box_{i}.off", *box(3 + i, (1 + 0.2 * i, 1, 0.3 + 0.1 * i)))
    for i in range(8):
        write_off(folder / f"cylinder_{i}.off", *cylinder(12 + 4 * i, 1 + 0.5 * i, 2 + i))
    (folder / "garbage.off").write_text("OFF\n3 1 0\n0 0 0\n")
    return folder


def table(path):
    """The table without the seconds (and with the output folders' names only)."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        del r["seconds"]
        r["output"] = os.path.basename(r["output"])
    return rows


def test_program_and_dask_give_the_same_table(inputs, fandisk_reference, tmp_path):
    # the program's serial run (--jobs 1; script_batch.sh checks that 2 jobs give the same)
    program = subprocess.run([PROGRAM, "batch", str(inputs), "--output-dir", str(tmp_path / "program"), "--jobs", "1",
                              "--quiet"])
    assert program.returncode == 1  # the garbage file
    expected = table(tmp_path / "program" / "batch_summary.csv")
    assert len(expected) == 25
    assert sum(r["status"] == "done" for r in expected) == 24
    assert [r["status"] for r in expected if "garbage" in r["mesh"]] == ["failed"]
    assert next(r for r in expected if r["output"] == "fandisk")["patches"] == str(fandisk_reference["patches"])

    out = tmp_path / "dask"
    rows = batch.run([str(inputs)], str(out), workers=2, progress=None)
    assert len(rows) == 25
    assert table(out / "batch_summary.csv") == expected
    with open(out / "batch_summary.jsonl") as f:
        assert len(f.readlines()) == 25

    # per-mesh outputs equal too
    for name in ["fandisk", "box_3", "cylinder_5"]:
        assert (out / name / "face_patches.txt").read_text() == \
            (tmp_path / "program" / name / "face_patches.txt").read_text()

    # resume: complete outputs are skipped, an incomplete one is done again, the failure retried
    (out / "rotor" / "summary.json").unlink()
    again = batch.run([str(inputs)], str(out), workers=2, progress=None)
    statuses = {os.path.basename(r["output"]): r["status"] for r in again}
    assert statuses["rotor"] == "done" and statuses["garbage"] == "failed"
    assert sum(s == "skipped" for s in statuses.values()) == 23
    resumed = table(out / "batch_summary.csv")
    for r in resumed:
        r["status"] = r["status"].replace("skipped", "done")
    assert resumed == expected


def test_command_line(inputs, fandisk_reference, tmp_path):
    env = dict(os.environ)
    ok = subprocess.run([sys.executable, "-m", "feature_segmentation.batch", str(inputs / "fandisk.off"),
                         str(inputs / "box_0.off"), "--output-dir", str(tmp_path / "cli"), "--workers", "1",
                         "--alpha", "1.0", "--crest-lines-on-clean-tessellations"], env=env, capture_output=True,
                        text=True)
    assert ok.returncode == 0, ok.stderr
    assert "progress: [1/2]" in ok.stderr and "s left" in ok.stderr
    rows = table(tmp_path / "cli" / "batch_summary.csv")
    assert rows[0]["patches"] == str(fandisk_reference["patches_alpha_1_with_crest_lines"])
    bad = subprocess.run([sys.executable, "-m", "feature_segmentation.batch", str(inputs / "fandisk.off"),
                          "--output-dir", str(tmp_path / "bad"), "--alpha", "nan"], env=env, capture_output=True,
                         text=True)
    assert bad.returncode == 2 and "alpha expects a finite number" in bad.stderr
    failing = subprocess.run([sys.executable, "-m", "feature_segmentation.batch", str(inputs / "garbage.off"),
                              "--output-dir", str(tmp_path / "failing"), "--workers", "1", "--quiet"], env=env)
    assert failing.returncode == 1
