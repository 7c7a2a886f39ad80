#!/usr/bin/python3
"""What the Python module costs over the C++ it wraps (issue 21: under 5%).

    bench/python_overhead.py [--build build] [--mesh examples/knot1.off] [--vertices 10000]
                             [--repeat 3]

The same job both ways, alternating, in one script: `cvtmesh remesh MESH OUT --vertices N
--quiet --json` (read, repair, remesh, report, write; the process's wall time) against the same
through the module (cvtmesh.read, cvtmesh.remesh, cvtmesh.write, timed inside a python3 process
started for it, once numpy and cvtmesh are imported: the interpreter's start-up and numpy's
import, about 0.1 s, are Python's, not the bindings'; they are shown apart). Both with the
defaults, so both measure the report's Hausdorff distance. The best of --repeat runs of each
is compared, as the machines are shared and noisy.
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

PYTHON_JOB = """
import sys, time
import numpy, cvtmesh
start = time.monotonic()
V, F = cvtmesh.read(sys.argv[1])
V2, F2, report = cvtmesh.remesh(V, F, vertices=int(sys.argv[3]))
cvtmesh.write(sys.argv[2], V2, F2)
print(time.monotonic() - start)
"""


def wall(command, env=None):
    """The command's wall time, and what it printed."""
    start = time.monotonic()
    out = subprocess.run(command, check=True, stdout=subprocess.PIPE, env=env, text=True).stdout
    return time.monotonic() - start, out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--mesh", default=str(ROOT / "examples" / "knot1.off"))
    parser.add_argument("--vertices", type=int, default=10000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    cli = os.path.join(args.build, "apps", "cvtmesh", "cvtmesh")
    env = dict(os.environ, PYTHONPATH=os.path.join(args.build, "python"))
    times = {"C++ (CLI)": [], "Python module": [], "Python start-up": []}
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.off")
        for _ in range(args.repeat):
            times["C++ (CLI)"].append(wall([cli, "remesh", args.mesh, out, "--vertices",
                                            str(args.vertices), "--quiet", "--json"])[0])
            total, inside = wall([sys.executable, "-c", PYTHON_JOB, args.mesh, out,
                                  str(args.vertices)], env)
            times["Python module"].append(float(inside))
            times["Python start-up"].append(total - float(inside))
    for name, values in times.items():
        print(f"{name:15s} best {min(values):.3f} s   runs " +
              " ".join(f"{v:.3f}" for v in values))
    ratio = min(times["Python module"]) / min(times["C++ (CLI)"])
    print(f"{os.path.basename(args.mesh)} -> {args.vertices} vertices: Python / C++ = {ratio:.3f} "
          f"(bindings cost {100 * (ratio - 1):+.1f}%; interpreter and numpy start-up "
          f"{min(times['Python start-up']):.2f} s more)")


if __name__ == "__main__":
    main()
