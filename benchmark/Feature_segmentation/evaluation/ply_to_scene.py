#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Turns segmentation.ply files written by feature_segmentation (ASCII PLY, a patch_id
and a colour per face) into one fs_scene file per mesh for render_scenes: the mesh and
one tile coloured by patch. Standard library only.

Usage: ply_to_scene.py SEGMENTATION.ply OUT.scene LABEL
"""
import sys


def read_segmentation_ply(path):
    with open(path) as f:
        if f.readline().strip() != "ply":
            raise SystemExit(f"{path}: not a PLY file")
        nv = nf = None
        face_props = []
        in_face = False
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "format" and w[1] != "ascii":
                raise SystemExit(f"{path}: not an ASCII PLY file")
            if w[0] == "element":
                in_face = w[1] == "face"
                if w[1] == "vertex":
                    nv = int(w[2])
                elif w[1] == "face":
                    nf = int(w[2])
            elif w[0] == "property" and in_face and w[1] != "list":
                face_props.append(w[2])
            elif w[0] == "end_header":
                break
        if nv is None or nf is None or face_props[-3:] != ["red", "green", "blue"]:
            raise SystemExit(f"{path}: expected vertices and faces with red, green, blue per face")
        points = [f.readline().split()[:3] for _ in range(nv)]
        faces, colours = [], []
        for _ in range(nf):
            w = f.readline().split()
            n = int(w[0])
            if n != 3:
                raise SystemExit(f"{path}: a face of {n} vertices (expected triangles)")
            faces.append(w[1:4])
            r, g, b = (int(x) for x in w[-3:])
            colours.append(f"{r:02x}{g:02x}{b:02x}")
        return points, faces, colours


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    points, faces, colours = read_segmentation_ply(sys.argv[1])
    with open(sys.argv[2], "w") as o:
        o.write(f"fs_scene 1\nvertices {len(points)}\n")
        o.writelines(" ".join(p) + "\n" for p in points)
        o.write(f"faces {len(faces)}\n")
        o.writelines(" ".join(t) + "\n" for t in faces)
        o.write(f"tile {sys.argv[3]}\ncolours\n")
        o.write("\n".join(colours) + "\n")
        o.write("segments 0\n")


if __name__ == "__main__":
    main()
