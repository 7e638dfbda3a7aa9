# SPDX-License-Identifier: GPL-3.0-or-later
"""Segments many meshes with Dask: ``feature_segmentation batch`` beyond one machine.

    python3 -m feature_segmentation.batch INPUTS... --output-dir DIR
        [--scheduler ADDRESS | --workers N] [--force] [program options]

INPUTS are mesh files, folders (searched recursively for .off, .obj, .ply, .stl) and
list files (.txt, one path per line), planned exactly as ``feature_segmentation batch``
plans them (same output folders). Without --scheduler a local cluster of N worker
processes (default: 2) runs the meshes; with it, any running Dask scheduler does (one
started on a Slurm or Kubernetes cluster, say). Each worker writes a mesh's outputs
itself (summary.json last), then its row is recorded, so a worker that dies loses no
finished mesh: a rerun skips every mesh whose outputs are complete (unless --force)
and the table is the same. The table, DIR/batch_summary.csv and .jsonl, is the one the
program writes: a row per mesh in input order. Exit status 1 if any mesh failed.

Program options: the segmentation options of the program, by the same flags
(``feature_segmentation.options()`` lists them; ``--help`` shows them).
"""
import argparse
import sys
import time

from . import _core

_TYPES = {"int": int, "float": float, "str": str}


def _add_program_options(parser):
    """The program's segmentation options, from the module's one table."""
    for keyword, o in _core.options().items():
        if o["type"] == "bool":
            # a switch on by default is turned off by its flag (--no-ridges), the others on
            parser.add_argument(o["flag"], dest=keyword, action="store_const", const=not o["default"],
                                default=None, help=o["help"])
        else:
            parser.add_argument(o["flag"], dest=keyword, type=_TYPES[o["type"]], metavar=o["type"].upper(),
                                help=o["help"])


def run_one(mesh, output, options):
    """Segments one mesh on a worker, writing its outputs; returns its row."""
    start = time.perf_counter()
    row = {"mesh": mesh, "output": output, "faces": 0, "patches": 0, "cut_cost": 0.0, "seconds": 0.0,
           "status": "done", "error": ""}
    try:
        row["faces"], row["patches"], row["cut_cost"] = _core.segment_file(mesh, output, **options)
    except MemoryError:
        row["status"], row["error"] = "failed", "out of memory"
    except Exception as e:  # the program's message, as its batch records it
        row["status"], row["error"] = "failed", str(e)
    row["seconds"] = time.perf_counter() - start
    return row


def plan(inputs, output_dir, force=False):
    """The rows of a batch: (rows, indices of the meshes still to segment)."""
    rows, todo = [], []
    for mesh, output in _core.batch_plan(inputs, output_dir):
        row = {"mesh": mesh, "output": output, "faces": 0, "patches": 0, "cut_cost": 0.0, "seconds": 0.0,
               "status": "", "error": ""}
        done = None if force else _core.finished_row(mesh, output)
        if done is not None:
            row["faces"], row["patches"], row["cut_cost"], row["seconds"] = done
            row["status"] = "skipped"
        else:
            todo.append(len(rows))
        rows.append(row)
    return rows, todo


def run(inputs, output_dir, options=None, scheduler=None, workers=2, force=False, progress=sys.stderr):
    """Runs a batch on Dask; returns the rows (also written as the table)."""
    from dask.distributed import Client, LocalCluster, as_completed
    import os
    options = dict(options or {})
    _core.check_options(**options)  # a bad option fails here, not on every worker
    os.makedirs(output_dir, exist_ok=True)
    rows, todo = plan(inputs, output_dir, force)
    if not rows:
        raise ValueError("batch: no mesh found in the inputs")
    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
    try:
        futures = {client.submit(run_one, rows[i]["mesh"], rows[i]["output"], options, key=f"fs-{i}-{time.time_ns()}",
                                 retries=1, pure=False): i for i in todo}
        finished, start = len(rows) - len(todo), time.perf_counter()
        for future in as_completed(futures):
            i = futures[future]
            rows[i] = future.result()
            finished += 1
            if progress is not None:
                r = rows[i]
                what = f"failed: {r['error']}" if r["status"] == "failed" else f"{r['patches']} patches"
                done_here = finished - (len(rows) - len(todo))
                left = (time.perf_counter() - start) / done_here * (len(rows) - finished)
                tail = f"; about {left:.0f} s left" if finished < len(rows) else ""
                print(f"progress: [{finished}/{len(rows)}] {r['mesh']}: {what}{tail}", file=progress, flush=True)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    _core.write_batch_summary(output_dir, rows)
    return rows


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m feature_segmentation.batch",
                                     description="Segments many meshes with Dask (a local cluster by default).")
    parser.add_argument("inputs", nargs="+", help="mesh files, folders of meshes, list files (.txt)")
    parser.add_argument("--output-dir", required=True, help="one folder per mesh goes into it, and the table")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: a local cluster)")
    parser.add_argument("--workers", type=int, default=2, help="worker processes of the local cluster (default: 2)")
    parser.add_argument("--force", action="store_true", help="segment again meshes whose outputs are complete")
    parser.add_argument("--quiet", action="store_true", help="no progress lines")
    _add_program_options(parser)
    a = parser.parse_args(argv)
    if a.workers < 1:
        parser.error("--workers must be >= 1")
    options = {k: getattr(a, k) for k in _core.options() if getattr(a, k) is not None}
    try:
        rows = run(a.inputs, a.output_dir, options, a.scheduler, a.workers, a.force,
                   None if a.quiet else sys.stderr)
    except (ValueError, TypeError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    failed = sum(r["status"] == "failed" for r in rows)
    if not a.quiet:
        print(f"batch: {len(rows)} meshes, {failed} failed; table in {a.output_dir}/batch_summary.csv",
              file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
