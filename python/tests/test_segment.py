# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module against the program on the same files, its edits, and its errors."""
import os
import subprocess
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import feature_segmentation as fs

MESHES = os.environ["FS_MESH_DIR"]
PROGRAM = os.path.join(os.environ["FS_BINARY_DIR"], "demo/Feature_segmentation/feature_segmentation")
FANDISK = os.path.join(MESHES, "fandisk.off")


def program_patches(mesh, out, *options):
    subprocess.run([PROGRAM, mesh, "--output-dir", str(out), "--quiet", *options], check=True)
    return np.loadtxt(out / "face_patches.txt", dtype=np.int64), np.loadtxt(out / "vertex_patches.txt",
                                                                              dtype=np.int64)


@pytest.fixture(scope="module")
def fandisk():
    return fs.read_mesh(FANDISK)


def test_read_mesh_shapes_and_types(fandisk):
    v, f = fandisk
    assert v.shape == (6475, 3) and v.dtype == np.float64
    assert f.shape == (12946, 3) and f.dtype == np.int64
    assert f.min() == 0 and f.max() == 6474


def test_segment_equals_the_program(fandisk, fandisk_reference, tmp_path):
    faces, vertices, result = fs.segment(*fandisk)
    program_faces, program_vertices = program_patches(FANDISK, tmp_path)
    assert np.array_equal(faces, program_faces)
    assert np.array_equal(vertices, program_vertices)
    assert result.patches == fandisk_reference["patches"] == faces.max() + 1
    assert result.faces == fandisk_reference["faces"] and result.vertices == fandisk_reference["vertices"]
    assert result.crease_edges == fandisk_reference["crease_edges"]
    assert set(result.seconds) >= {"load", "segmentation"}


def test_options_by_keyword_equal_the_programs(fandisk, tmp_path):
    faces, _, result = fs.segment(*fandisk, alpha=1.0, crease_angle=180, radius=0)
    program_faces, _ = program_patches(FANDISK, tmp_path, "--alpha", "1.0", "--crease-angle", "180", "--radius", "0")
    assert np.array_equal(faces, program_faces)
    assert result.crease_edges == 0
    # the switches of the creases: crest lines too, no curvature discontinuities
    faces, _, result = fs.segment(*fandisk, crest_lines_on_clean_tessellations=True, tangent_discontinuities=False)
    program_faces, _ = program_patches(FANDISK, tmp_path / "switches", "--crest-lines-on-clean-tessellations",
                                       "--no-tangent-discontinuities")
    assert np.array_equal(faces, program_faces)
    assert result.crease_edges == 876  # without the 50 edges of the blends' tangent lines
    assert result.feature_edges > result.crease_edges  # and the crest lines


def test_float32_and_int32_arrays_are_accepted(fandisk):
    v, f = fandisk
    a, _, _ = fs.segment(v, f)
    b, _, _ = fs.segment(v.astype(np.float64), f.astype(np.int32))
    assert np.array_equal(a, b)


@pytest.mark.parametrize("vertices, faces, message", [
    (np.zeros((4, 2)), np.array([[0, 1, 2]]), "vertices must be an \\(n, 3\\) array"),
    (np.zeros((4, 3)), np.array([[0, 1]]), "faces must be an \\(m, 3\\) array"),
    (np.zeros((4, 3)), np.array([[0.0, 1.0, 2.0]]), "faces must hold integers"),
    (np.array([["a", "b", "c"]]), np.array([[0, 0, 0]]), "vertices must hold numbers"),
    (np.eye(3), np.array([[0, 1, 3]]), "refers to vertex 3, out of range"),
    (np.eye(3), np.array([[0, 1, -1]]), "refers to vertex -1"),
    (np.array([[0, 0, 0], [1, 0, 0], [np.nan, 1, 0]]), np.array([[0, 1, 2]]), "NaN or infinite"),
])
def test_bad_arrays_raise_value_error(vertices, faces, message):
    with pytest.raises(ValueError, match=message):
        fs.segment(vertices, faces)


def test_bad_options_raise(fandisk):
    with pytest.raises(ValueError, match="alpha expects a finite number"):
        fs.segment(*fandisk, alpha=float("nan"))
    with pytest.raises(ValueError, match="radius must be a number in \\[0, 1\\]"):
        fs.segment(*fandisk, radius=2)
    with pytest.raises(ValueError, match="solver must be"):
        fs.segment(*fandisk, solver="magic")
    with pytest.raises(TypeError, match="unexpected keyword argument 'alpah'"):
        fs.segment(*fandisk, alpah=0.7)


@pytest.mark.parametrize("options, error, message", [
    (dict(rings=2.0), TypeError, "^rings must be an integer \\(got float\\)$"),
    (dict(rings=True), TypeError, "^rings must be an integer \\(got bool\\)$"),
    (dict(alpha="1"), TypeError, "^alpha must be a number \\(got str\\)$"),
    (dict(ridges=1), TypeError, "^ridges must be a bool \\(got int\\)$"),
    (dict(feature_edges=3), TypeError, "^feature_edges must be a str \\(got int\\)$"),
    (dict(threads=2), TypeError, "^unexpected keyword argument 'threads'$"),
    (dict(rings=0), ValueError, "^rings must be an integer >= 1 \\(got 0\\)$"),
    (dict(rings=10**30), ValueError, "^rings is out of range"),
    (dict(crease_angle=0), ValueError, "^crease_angle must be > 0 degrees \\(got '0'\\)$"),
    (dict(crease_filter=1001), ValueError, "^crease_filter must be an integer in 0 .. 1000"),
])
def test_options_are_typed_and_checked_as_the_program_checks_them(options, error, message):
    """A keyword is the program's option: the same check and message, named as the keyword;
    a value of the wrong type is a TypeError (no text is parsed)."""
    with pytest.raises(error, match=message):
        fs.check_options(**options)


def test_options_lists_the_program_flags_with_their_defaults():
    options = fs.options()
    assert options["alpha"] == {"type": "float", "default": 0.6, "flag": "--alpha",
                                "help": "how strongly features cut: larger, more patches"}
    assert options["ridges"]["flag"] == "--no-ridges" and options["ridges"]["default"] is True
    assert options["full_graph"]["flag"] == "--full-graph" and options["full_graph"]["default"] is False
    assert options["feature_edges"]["default"] is None
    usage = subprocess.run([PROGRAM, "--help"], capture_output=True, text=True, check=True).stdout
    for keyword, o in options.items():
        assert o["flag"] in usage, keyword
        assert o["flag"].replace("--no-", "--").lstrip("-").replace("-", "_") == keyword
    # every default is accepted, and None keeps the default
    fs.check_options(**{k: o["default"] for k, o in options.items()})


def test_numpy_scalars_and_paths_are_accepted(fandisk, tmp_path):
    a, _, r = fs.segment(*fandisk, alpha=np.float32(0.75), rings=np.int64(2))
    b, _, s = fs.segment(*fandisk, alpha=0.75, rings=2)
    assert np.array_equal(a, b) and r.cut_cost == s.cut_cost
    # a pathlib.Path is a file name: this one is read, and is missing
    with pytest.raises(ValueError, match="none.txt: no such file"):
        fs.segment(*fandisk, feature_edges=tmp_path / "none.txt")


def test_a_mesh_the_library_refuses_raises_value_error():
    # two triangles folded onto each other across their edge
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, 2, 0]], dtype=float)
    f = np.array([[0, 1, 2], [1, 0, 3]])
    with pytest.raises(ValueError, match="overlap"):
        fs.segment(v, f)


def test_an_edge_of_four_faces_is_cut_apart():
    # two tetrahedra sharing the edge 0-1: repaired into two closed tetrahedra, as the
    # program's reader does (script_file_variants.sh), every face segmented
    v = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0.3], [0.5, 0.3, 1], [0.5, -1, 0.3], [0.5, -0.3, -1]])
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 1], [0, 1, 5], [0, 5, 4], [1, 4, 5]])
    faces, vertices, result = fs.segment(v, f)
    assert faces.shape == (8,) and faces.min() >= 0
    assert result.faces == 8 and result.vertices == 8  # the edge's two vertices copied once each


def test_nested_lists_are_arrays(fandisk):
    v, f = fandisk
    a, _, _ = fs.segment(v[:200].tolist(), f[np.all(f < 200, axis=1)].tolist())
    b, _, _ = fs.segment(v[:200], f[np.all(f < 200, axis=1)])
    assert np.array_equal(a, b)


def test_what_is_no_array_gives_a_short_value_error():
    with pytest.raises(ValueError, match="^vertices must be an array or a nested sequence of numbers") as e:
        fs.segment([[0, 0, 0], [1, 0]] * 10000, [[0, 1, 2]])
    assert len(str(e.value)) < 200  # the input is not echoed


def test_a_missing_file_raises_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError) as e:
        fs.read_mesh(str(tmp_path / "no_such_mesh.off"))
    assert e.value.filename == str(tmp_path / "no_such_mesh.off")


# The paper's editing moves the crest lines' alpha_e: on fandisk, a clean CAD tessellation
# whose feature lines are by default its creases alone, the editing tests ask for them.
CREST_LINES = {"crest_lines_on_clean_tessellations": True}


def test_edits_and_a_save_that_the_program_replays(fandisk, fandisk_reference, tmp_path):
    seg = fs.Segmentation(*fandisk, **CREST_LINES)
    assert seg.patches == fandisk_reference["patches"] and seg.alpha == 0.6
    assert seg.set_alpha(1.0) == fandisk_reference["set_alpha_1_with_crest_lines"]
    patches = seg.face_patches()
    other = int(np.argmax(patches != patches[0]))
    merged = fandisk_reference["merge_after_set_alpha_1"]
    assert seg.merge(np.array([0, other])) == merged
    assert seg.face_patches()[0] == seg.face_patches()[other]
    everything = np.arange(fandisk_reference["faces"])
    assert seg.refine(everything, 0.3) >= merged
    assert seg.coarsen(everything, 0.3) == merged
    assert seg.undo() and seg.undo()
    assert seg.patches == merged
    assert seg.redo() and seg.redo()  # the refine and the coarsen again
    assert seg.patches == merged
    assert not seg.redo()
    assert seg.edits[:2] == ["alpha 1", f"merge faces 0 {other}"]
    with pytest.raises(ValueError, match="out of range"):
        seg.merge([0, 12946])
    with pytest.raises(ValueError, match="faces must be a 1-D array"):
        seg.refine(np.zeros((2, 2), dtype=int), 0.1)
    seg.save(str(tmp_path / "saved"))
    lines = (tmp_path / "saved" / "edits.txt").read_text().splitlines()
    flags = lines[1].removeprefix("# replay: feature_segmentation MESH ").removesuffix(" --edits edits.txt").split()
    subprocess.run([PROGRAM, FANDISK, *flags, "--edits", str(tmp_path / "saved" / "edits.txt"), "--output-dir",
                    str(tmp_path / "replay"), "--quiet"], check=True)
    assert (tmp_path / "saved" / "face_patches.txt").read_text() == \
        (tmp_path / "replay" / "face_patches.txt").read_text()
    assert np.array_equal(np.loadtxt(tmp_path / "saved" / "face_patches.txt", dtype=np.int64), seg.face_patches())


def test_sketch_adds_feature_edges(fandisk):
    v, f = fandisk
    seg = fs.Segmentation(v, f)
    before = seg.result().feature_edges
    seg.sketch(np.array([v[f[0, 0]], v[f[600, 0]]]))
    assert seg.result().feature_edges > before
    assert seg.undo() and seg.result().feature_edges == before
    with pytest.raises(ValueError, match="alpha must be > 1"):
        seg.sketch(np.array([v[0], v[1]]), alpha=1.0)
    with pytest.raises(ValueError, match="\\(k, 3\\) array, k >= 2"):
        seg.sketch(np.array([v[0]]))
    with pytest.raises(ValueError, match="2 to 1000 points \\(got 1001\\)"):
        seg.sketch(np.zeros((1001, 3)))


@pytest.mark.parametrize("alpha", [5e-324, 1e308, -2e9])
def test_an_edit_that_would_not_replay_is_refused(fandisk, alpha):
    """The edit script's, the editor's and Python's edits meet one check: a subnormal alpha
    does not read back from its script line, and 1e308 makes the cut cost infinite."""
    seg = fs.Segmentation(*fandisk)
    with pytest.raises(ValueError, match="^alpha: the value must be 0 or of magnitude between 1e-9 and 1e9"):
        seg.set_alpha(alpha)
    assert seg.edits == []


def test_boundaries_feature_lines_and_creases(fandisk, fandisk_reference):
    seg = fs.Segmentation(*fandisk, **CREST_LINES)
    curves = seg.boundaries()
    assert curves and all(c.ndim == 2 and c.shape[1] == 3 and len(c) >= 2 for c in curves)
    raw = seg.boundaries(smooth=False)
    length = lambda cs: sum(np.linalg.norm(np.diff(c, axis=0), axis=1).sum() for c in cs)
    assert length(curves) < length(raw)  # the smoothing shortens them
    lines = seg.feature_lines()
    assert lines and {line["kind"] for line in lines} <= {"ridge", "valley", "seam_line", "user"}
    assert seg.creases().shape == (fandisk_reference["crease_edges"], 2, 3)


def test_threads_segment_at_once_with_the_serial_results():
    meshes = [fs.read_mesh(os.path.join(MESHES, name)) for name in
              ["fandisk.off", "rotor.off", "sphere.off", "pinion.off"]]
    serial = [fs.segment(v, f)[0] for v, f in meshes]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(lambda m: fs.segment(*m)[0], meshes * 2))
    for i, labels in enumerate(parallel):
        assert np.array_equal(labels, serial[i % 4])


@pytest.mark.parametrize("name", ["fandisk.off", "anchor_dense.off"])
def test_alpha_is_the_granularity_control_on_cad_parts(name):
    """On a clean CAD tessellation alpha orders the evidence: below the default the weakest
    creases merge first, above it the crest lines of the curved faces add patches, so that
    the sweep 0.1 .. 2.0 gives at least six counts, never fewer patches for a larger alpha,
    and the default's count at 0.6."""
    v, f = fs.read_mesh(os.path.join(MESHES, name))
    seg = fs.Segmentation(v, f)
    default = seg.result().patches
    counts = []
    for k in range(1, 21):
        seg.set_alpha(k / 10)
        counts.append(seg.result().patches)
    assert counts == sorted(counts), counts
    assert len(set(counts)) >= 6, counts
    assert counts[5] == default, counts
