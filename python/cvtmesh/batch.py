"""Remesh every mesh of a folder: `python3 -m cvtmesh.batch IN_DIR OUT_DIR --vertices N`.

Locally the meshes are spread over a process pool (--jobs, with a progress bar); with
--scheduler ADDRESS they run on a Dask cluster instead, whose workers must be able to
`import cvtmesh`. Each mesh gets one JSON row in OUT_DIR/cvtmesh-batch.jsonl: its name, the
output file, "ok" or "error" and the message, the seconds it took, and the remesh's report (the
keys of `cvtmesh remesh --json`). A failing mesh is recorded and the batch goes on. Rows are
appended as meshes finish and outputs are written atomically, so an interrupted batch loses
nothing: run it again and it skips the meshes already done with the same settings (and retries
the failed ones);
at the end the file holds one row per mesh.
"""

import argparse
import concurrent.futures
import json
import multiprocessing
import os
import signal
import sys
import tempfile
import time

MESH_EXTENSIONS = (".obj", ".off", ".ply", ".stl")
ROWS = "cvtmesh-batch.jsonl"
# remesh() keywords the command line passes on (the CLI's names, with underscores).
REMESH_OPTIONS = ("vertices", "edge_length", "edge_length_rel", "seed", "iterations",
                  "feature_angle", "no_features", "no_hausdorff", "time_limit",
                  "topology_rounds", "polish_rounds", "fill_holes")


def remesh_file(source, target, settings, threads):
    """Remesh one file into another; never raises: the row says what happened."""
    import warnings

    import cvtmesh  # in the worker: each process imports the module once

    start = time.monotonic()
    row = {"mesh": os.path.basename(source), "output": os.path.basename(target),
           "settings": settings}
    with warnings.catch_warnings(record=True) as caught:  # repairs: into the row
        warnings.simplefilter("always")
        try:
            V, F = cvtmesh.read(source)
            V2, F2, report = cvtmesh.remesh(V, F, threads=threads, **settings)
            cvtmesh.write(target, V2, F2)
            row.update(status="ok", error=None, report=report)
        except Exception as e:  # noqa: BLE001  (whatever it is, the batch goes on)
            row.update(status="error", error=f"{type(e).__name__}: {e}", report=None)
    row["warnings"] = [str(w.message) for w in caught]
    row["seconds"] = round(time.monotonic() - start, 3)
    return row


def failure_row(task, message):
    """The row of a mesh whose task never returned one (its worker died, say)."""
    source, target, settings = task[:3]
    return {"mesh": os.path.basename(source), "output": os.path.basename(target),
            "settings": settings, "status": "error", "error": message, "report": None,
            "seconds": None}


class Rows:
    """The rows file: read at the start, appended to (and flushed) as meshes finish, rewritten
    atomically with one row per mesh at the end."""

    def __init__(self, folder):
        self.path = os.path.join(folder, ROWS)
        self.latest = {}
        if os.path.exists(self.path):
            with open(self.path, encoding="utf-8") as f:
                for line in f:
                    try:
                        row = json.loads(line)
                        self.latest[row["mesh"]] = row
                    except (ValueError, KeyError):
                        pass  # a line cut short by a crash: that mesh runs again
        self.file = open(self.path, "a", encoding="utf-8")

    def done(self, name, output, settings):
        """Remeshed before, into `output`, with the same settings, and still there."""
        row = self.latest.get(name)
        return (row is not None and row["status"] == "ok" and row["output"] == output
                and row.get("settings") == settings
                and os.path.exists(os.path.join(os.path.dirname(self.path), output)))

    def add(self, row):
        self.latest[row["mesh"]] = row
        self.file.write(json.dumps(row) + "\n")
        self.file.flush()
        os.fsync(self.file.fileno())

    def compact(self):
        self.file.close()
        folder = os.path.dirname(self.path)
        handle, temporary = tempfile.mkstemp(dir=folder, prefix=".cvtmesh-batch-")
        with os.fdopen(handle, "w", encoding="utf-8") as f:
            for name in sorted(self.latest):
                f.write(json.dumps(self.latest[name]) + "\n")
        os.chmod(temporary, 0o644)
        os.replace(temporary, self.path)


def start_worker():
    """A pool worker only remeshes: its allocator keeps freed memory for the next evaluation
    (cvtmesh.keep_freed_memory; Dask workers, which are not ours, are left as they are)."""
    import cvtmesh

    cvtmesh.keep_freed_memory()


def run_local(tasks, jobs, on_row):
    """On a process pool. Workers are spawned, not forked: a forked copy of a process whose
    oneTBB threads have started can deadlock."""
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(jobs, mp_context=context,
                                                initializer=start_worker) as pool:
        futures = {pool.submit(remesh_file, *task): task for task in tasks}
        try:
            for future in concurrent.futures.as_completed(futures):
                try:
                    on_row(future.result())
                except concurrent.futures.process.BrokenProcessPool:
                    on_row(failure_row(futures[future],
                                       "a worker process died (crash or out of memory) while "
                                       "remeshing this mesh or one beside it"))
        except KeyboardInterrupt:
            for future in futures:
                future.cancel()
            for process in list(pool._processes.values()):  # noqa: SLF001 (no public way)
                process.terminate()
            raise


def run_dask(tasks, address, on_row):
    """On a Dask cluster: one task per mesh; Dask places and retries them."""
    from distributed import Client, as_completed

    with Client(address, timeout="30s") as client:
        futures = {client.submit(remesh_file, *task, pure=False,
                                 key=f"cvtmesh-{os.path.basename(task[0])}-{time.time_ns()}"): task
                   for task in tasks}
        try:
            for future in as_completed(futures):
                try:
                    on_row(future.result())
                except Exception as e:  # the worker died, or the task could not run there
                    on_row(failure_row(futures[future], f"{type(e).__name__}: {e}"))
        except KeyboardInterrupt:
            client.cancel(list(futures))
            raise


def progress_bar(total, quiet):
    if quiet:
        return None
    try:
        from tqdm import tqdm
    except ImportError:
        return None
    return tqdm(total=total, unit="mesh", file=sys.stderr, dynamic_ncols=True)


def parse(argv):
    parser = argparse.ArgumentParser(
        prog="python3 -m cvtmesh.batch",
        description="Remesh every mesh (.obj .off .ply .stl) of a folder into another.")
    parser.add_argument("input", metavar="IN_DIR")
    parser.add_argument("output", metavar="OUT_DIR", help="created if missing")
    size = parser.add_mutually_exclusive_group(required=True)
    size.add_argument("--vertices", type=int, help="output vertices per mesh")
    size.add_argument("--edge-length", type=float, help="target edge length, in each mesh's units")
    size.add_argument("--edge-length-rel", type=float,
                      help="target edge length as a fraction of each mesh's bbox diagonal")
    parser.add_argument("--format", choices=[e[1:] for e in MESH_EXTENSIONS],
                        help="output format (default: each input's own)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count(),
                        help="meshes remeshed at once on this machine (default: all cores)")
    parser.add_argument("--threads", type=int, default=0,
                        help="threads per mesh (default: cores / jobs, at least 1)")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="a Dask scheduler (tcp://host:8786): run there instead")
    parser.add_argument("--seed", type=int)
    parser.add_argument("--iterations", type=int)
    parser.add_argument("--feature-angle", type=float)
    parser.add_argument("--no-features", action="store_true", default=None)
    parser.add_argument("--no-hausdorff", action="store_true", default=None)
    parser.add_argument("--time-limit", type=float, help="seconds per mesh")
    parser.add_argument("--topology-rounds", type=int)
    parser.add_argument("--polish-rounds", type=int)
    parser.add_argument("--fill-holes", type=float, nargs="?", const=10.0, metavar="E",
                        help="fill each input's holes under E edge lengths round first "
                             "(default E: 10)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    return parser.parse_args(argv)


def main(argv=None):
    args = parse(argv)
    if not os.path.isdir(args.input):
        print(f"cvtmesh.batch: error: {args.input}: not a folder", file=sys.stderr)
        return 1
    if os.path.realpath(args.input) == os.path.realpath(args.output):
        print(f"cvtmesh.batch: error: {args.output}: is the input folder", file=sys.stderr)
        return 1
    os.makedirs(args.output, exist_ok=True)
    names = sorted(n for n in os.listdir(args.input)
                   if n.lower().endswith(MESH_EXTENSIONS)
                   and os.path.isfile(os.path.join(args.input, n)))
    targets = {n: os.path.splitext(n)[0] + "." + args.format if args.format else n
               for n in names}
    if len(set(targets.values())) < len(targets):
        print("cvtmesh.batch: error: two inputs would have the same output name "
              "(same stem, different extensions); drop --format", file=sys.stderr)
        return 1
    settings = {k: getattr(args, k) for k in REMESH_OPTIONS if getattr(args, k) is not None}
    settings.setdefault("quiet", True)
    jobs = max(1, args.jobs)
    # Locally, the cores are shared out between the jobs; a Dask worker runs one task per
    # thread it has, so each mesh gets one unless told otherwise.
    threads = args.threads or (1 if args.scheduler else max(1, (os.cpu_count() or 1) // jobs))

    rows = Rows(args.output)
    todo = [n for n in names if not rows.done(n, targets[n], settings)]
    if len(todo) < len(names) and not args.quiet:
        print(f"cvtmesh.batch: {len(names) - len(todo)} of {len(names)} meshes done before, "
              "skipped", file=sys.stderr)
    tasks = [(os.path.join(args.input, n), os.path.join(args.output, targets[n]), settings,
              threads) for n in todo]
    bar = progress_bar(len(tasks), args.quiet)
    failed = []

    def on_row(row):
        rows.add(row)
        if row["status"] != "ok":
            failed.append(row)
        if bar is not None:
            bar.update(1)

    start = time.monotonic()
    try:
        if args.scheduler:
            run_dask(tasks, args.scheduler, on_row)
        elif tasks:
            run_local(tasks, jobs, on_row)
    except KeyboardInterrupt:
        if bar is not None:
            bar.close()
        print(f"cvtmesh.batch: interrupted; {len(rows.latest)} rows kept in {rows.path}; "
              "run again to finish", file=sys.stderr)
        rows.file.close()
        return 128 + signal.SIGINT
    if bar is not None:
        bar.close()
    rows.compact()
    for row in failed:
        print(f"cvtmesh.batch: {row['mesh']}: {row['error']}", file=sys.stderr)
    if not args.quiet:
        print(f"cvtmesh.batch: {len(tasks)} meshes in {time.monotonic() - start:.1f} s, "
              f"{len(failed)} failed; rows in {rows.path}", file=sys.stderr)
    return 2 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
