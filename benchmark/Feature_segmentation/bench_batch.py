#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Batch throughput: `feature_segmentation batch` at 1 and 2 jobs and the Dask runner
(python3 -m feature_segmentation.batch, a local cluster) at 1 and 2 workers, on CGAL's
demo meshes (BUILD_DIR/data/meshes) plus, when present, the 14 CAD parts of
$FEATURE_SEGMENTATION_DATA/cad (or --data DIR). Every run is --force (no mesh skipped);
prints a table (meshes per minute, faces per second, wall seconds) and writes CSV, with
its provenance (program, arguments, machine, date) in NAME.provenance.txt beside it.

Usage: PYTHONPATH=BUILD_DIR/python bench_batch.py --build BUILD_DIR [--data DIR] [--out FILE]
"""
import argparse
import csv
import datetime
import glob
import os
import platform
import subprocess
import sys
import tempfile
import time


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", required=True, help="the build folder (program, data/meshes, python)")
    p.add_argument("--data", default=os.environ.get("FEATURE_SEGMENTATION_DATA"))
    p.add_argument("--out", default="bench_batch.csv")
    a = p.parse_args()
    program = os.path.join(a.build, "demo/Feature_segmentation/feature_segmentation")
    meshes = sorted(glob.glob(os.path.join(a.build, "data/meshes/*.off")))
    sets = "CGAL's demo meshes"
    if a.data and os.path.isdir(os.path.join(a.data, "cad")):
        meshes += sorted(glob.glob(os.path.join(a.data, "cad/*.obj")))
        sets += " and the 14 CAD parts"
    else:
        print("CAD parts skipped: no --data DIR and no $FEATURE_SEGMENTATION_DATA with cad/", file=sys.stderr)
    env = dict(os.environ, PYTHONPATH=os.path.join(a.build, "python"))
    rows = []
    with tempfile.TemporaryDirectory() as work:
        listing = os.path.join(work, "meshes.txt")
        with open(listing, "w") as f:
            f.write("\n".join(meshes) + "\n")
        runs = [("program batch", n, [program, "batch", listing, "--jobs", str(n)]) for n in (1, 2)]
        runs += [("Dask (local cluster)", n, ["/usr/bin/python3", "-m", "feature_segmentation.batch", listing,
                                              "--workers", str(n)]) for n in (1, 2)]
        for name, n, command in runs:
            out = os.path.join(work, f"out_{len(rows)}")
            start = time.perf_counter()
            subprocess.run(command + ["--output-dir", out, "--force", "--quiet"], env=env, check=False)
            seconds = time.perf_counter() - start
            with open(os.path.join(out, "batch_summary.csv")) as f:
                table = list(csv.DictReader(f))
            faces = sum(int(r["faces"]) for r in table)
            failed = sum(r["status"] == "failed" for r in table)
            rows.append([name, n, len(table), failed, faces, seconds, 60 * len(table) / seconds, faces / seconds])
    print(f"Batch throughput on {sets} ({len(meshes)} meshes), {cpu_name()}, {os.cpu_count()} cores\n")
    print("| runner | workers | meshes | failed | faces | seconds | meshes/min | faces/s |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]} | {r[5]:.1f} | {r[6]:.0f} | {r[7]:.0f} |")
    with open(a.out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["runner", "workers", "meshes", "failed", "faces", "seconds", "meshes_per_minute", "faces_per_second"])
        w.writerows(rows)
    provenance = os.path.splitext(a.out)[0] + ".provenance.txt"
    with open(provenance, "w") as f:
        f.write(f"program: bench_batch.py\narguments: {' '.join(sys.argv[1:])}\n"
                f"machine: {cpu_name()}, {os.cpu_count()} cores\n"
                f"date: {datetime.datetime.now(datetime.timezone.utc).date().isoformat()}\n")
    print(f"\nCSV: {a.out} (provenance: {provenance})")


if __name__ == "__main__":
    main()
