#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Converts a gmsh mesh (MSH 2 ASCII) into NAME.obj and NAME.labels: the triangles, and
the surface entity (the B-rep face) of each, one per line in the OBJ's face order; the
format of the CAD parts that evaluate_quality reads.

Usage: msh_to_obj_labels.py IN.msh OUT_STEM"""
import sys


def main(msh_path, stem):
    nodes, triangles = {}, []
    with open(msh_path) as msh:
        lines = iter(msh.read().split("\n"))
    for line in lines:
        if line == "$MeshFormat":
            version = next(lines).split()[0]
            if not version.startswith("2"):
                sys.exit(f"{msh_path}: MSH version {version}; run gmsh with -format msh2")
        elif line == "$Nodes":
            for _ in range(int(next(lines))):
                i, x, y, z = next(lines).split()
                nodes[int(i)] = (x, y, z)
        elif line == "$Elements":
            for _ in range(int(next(lines))):
                fields = [int(t) for t in next(lines).split()]
                if fields[1] != 2:  # triangles only
                    continue
                number_of_tags = fields[2]
                entity = fields[4] if number_of_tags >= 2 else fields[3]
                triangles.append((entity, fields[3 + number_of_tags:6 + number_of_tags]))
    if not triangles:
        sys.exit(f"{msh_path}: no triangles")
    index = {}
    for _, corners in triangles:
        for n in corners:
            index.setdefault(n, len(index) + 1)
    with open(stem + ".obj", "w") as obj:
        obj.write(f"# {msh_path}: {len(triangles)} triangles of gmsh\n")
        for n in index:
            obj.write("v {} {} {}\n".format(*nodes[n]))
        for _, corners in triangles:
            obj.write("f {} {} {}\n".format(*(index[n] for n in corners)))
    with open(stem + ".labels", "w") as labels:
        labels.write("".join(f"{entity}\n" for entity, _ in triangles))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
