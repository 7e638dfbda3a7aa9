# SPDX-License-Identifier: GPL-3.0-or-later
"""Feature-aligned mesh segmentation by correlation clustering (Zhuang et al. 2017).

numpy arrays in, numpy arrays out, over the same pipeline as the program
``feature_segmentation`` (same mesh repairs, options, checks, edits and outputs)::

    import feature_segmentation as fs
    vertices, faces = fs.read_mesh("fandisk.off")
    face_patches, vertex_patches, result = fs.segment(vertices, faces, alpha=0.8)
    print(result.patches, result.cut_cost, result.seconds)

    seg = fs.Segmentation(vertices, faces)     # precompute once, then edit
    seg.set_alpha(1.0); seg.merge([0, 17]); seg.undo()
    seg.save("out")                            # the program's outputs and edits.txt

Options are keywords, the program's flags by another spelling (``--crease-angle`` is
``crease_angle``, ``--no-ridges`` is ``ridges=False``); ``options()`` lists them with
their types, defaults and help. A value of the wrong type raises TypeError, a value
out of range or bad input ValueError, with the program's message. The computation releases the GIL: threads segment meshes
at once. Many files: ``python3 -m feature_segmentation.batch`` (local or Dask).
"""
from ._core import (Result, Segmentation, read_mesh, segment_file, options, check_options, batch_plan,
                    finished_row, write_batch_summary)

__all__ = ["segment", "read_mesh", "Segmentation", "Result", "segment_file", "options", "check_options"]


def segment(vertices, faces, **options):
    """Segments a triangle mesh.

    vertices: (n, 3) float array; faces: (m, 3) integer array of vertex indices.
    Returns (face_patches, vertex_patches, result): int64 arrays with the patch of every
    row of `faces` and of `vertices` (-1 for a vertex no face uses), and a Result
    (patches, cut_cost, faces, vertices, feature_edges, crease_edges, seconds per stage).
    """
    s = Segmentation(vertices, faces, **options)
    face_patches, vertex_patches = s.patch_arrays()  # one smoothing for both
    return face_patches, vertex_patches, s.result()
