#!/usr/bin/python3
"""Batch remeshing on Dask against the local process pool (issue 21: within 1.2x).

    bench/batch.py [--build build] [--data ../shared/data/corpus] [--vertices 1000] [--jobs 2]

Runs `python3 -m cvtmesh.batch DATA OUT --vertices N` twice into fresh folders, in one script:
on the local process pool (--jobs J), then on a Dask cluster of J single-threaded worker
processes started here on the loopback address (--scheduler). Prints both wall times (the
cluster's start-up not counted), their ratio, how many meshes each remeshed, and the sum of
the meshes' own times (work; the wall time times the jobs, less that, is idle or overhead).
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def run(data, out, options, env):
    start = time.monotonic()
    process = subprocess.run([sys.executable, "-m", "cvtmesh.batch", data, out, "--quiet",
                              *options], env=env, capture_output=True, text=True)
    seconds = time.monotonic() - start
    with open(os.path.join(out, "cvtmesh-batch.jsonl"), encoding="utf-8") as f:
        rows = [json.loads(line) for line in f]
    ok = sum(row["status"] == "ok" for row in rows)
    work = sum(row["seconds"] or 0 for row in rows)
    return seconds, ok, len(rows), process.returncode, work


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--data", default=str(ROOT.parent / "shared" / "data" / "corpus"))
    parser.add_argument("--vertices", type=int, default=1000)
    parser.add_argument("--jobs", type=int, default=os.cpu_count())
    args = parser.parse_args()
    python = os.path.join(args.build, "python")
    env = dict(os.environ, PYTHONPATH=python)
    sys.path.insert(0, python)  # the Dask workers below are processes forked from this one
    os.environ["PYTHONPATH"] = python
    from distributed import LocalCluster

    size = ["--vertices", str(args.vertices)]
    with tempfile.TemporaryDirectory() as tmp:
        pool = run(args.data, os.path.join(tmp, "pool"), size + ["--jobs", str(args.jobs)], env)
        with LocalCluster(n_workers=args.jobs, threads_per_worker=1, processes=True,
                          host="127.0.0.1", dashboard_address=None) as cluster:
            dask = run(args.data, os.path.join(tmp, "dask"),
                       size + ["--scheduler", cluster.scheduler_address], env)
    for name, (seconds, ok, rows, code, work) in (("process pool", pool), ("Dask", dask)):
        print(f"{name:12s} {seconds:7.1f} s   {ok}/{rows} meshes ok   exit {code}   "
              f"{work:7.1f} s of work (sum over meshes)")
    print(f"{os.path.basename(os.path.normpath(args.data))} at {args.vertices} vertices, "
          f"{args.jobs} jobs: Dask / pool = {dask[0] / pool[0]:.3f}")


if __name__ == "__main__":
    main()
