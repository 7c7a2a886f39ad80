#!/usr/bin/python3
"""Scale benchmark (issue 22): how far cvtmesh remesh goes, with time and peak memory.

    bench/scale.py [--build build] [--data DIR] [--only NAME,...] [--threads T] [--timeout S]

Cases (inputs made here with numpy, or taken from the shared data):
  torus-2M        a torus of 2,000,000 triangles            -> 100,000 vertices
  igea-500k       ../shared/data/igea.ply (269k triangles)    -> 500,000 vertices
  10k-components  10,000 icosahedra (20 triangles each)       -> 120,000 vertices
  one-triangle    a single triangle                           -> 100,000 vertices

Each is one `cvtmesh remesh IN OUT --vertices N --json --no-hausdorff` process; the row gives
its wall time, its peak resident memory (getrusage of the child), the issue's memory bound
(200 bytes per input triangle + 300 per seed) and the output's validity and quality.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def write_binary_ply(path, vertices, triangles):
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {len(vertices)}\nproperty double x\nproperty double y\nproperty double z\n"
        f"element face {len(triangles)}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    faces = np.zeros(len(triangles), dtype=[("n", "u1"), ("v", "<i4", (3,))])
    faces["n"] = 3
    faces["v"] = triangles
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(np.ascontiguousarray(vertices, dtype="<f8").tobytes())
        f.write(faces.tobytes())


def torus(nu, nv, big=1.0, small=0.35):
    u, v = np.meshgrid(np.arange(nu) * 2 * np.pi / nu, np.arange(nv) * 2 * np.pi / nv,
                       indexing="ij")
    points = np.stack([(big + small * np.cos(v)) * np.cos(u),
                       (big + small * np.cos(v)) * np.sin(u), small * np.sin(v)], -1)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    a, b = i * nv + j, ((i + 1) % nu) * nv + j
    c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
    tris = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                           np.stack([a, c, d], -1).reshape(-1, 3)])
    return points.reshape(-1, 3), tris


def icosahedra(count, spacing=3.0):
    t = (1 + 5 ** 0.5) / 2
    v = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
                  [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]], float)
    v /= np.linalg.norm(v[0])
    f = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9],
                  [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2],
                  [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
                  [8, 6, 7], [9, 8, 1]])
    side = int(np.ceil(count ** (1 / 3)))
    centres = np.array([(x, y, z) for x in range(side) for y in range(side) for z in range(side)],
                       float)[:count] * spacing
    points = (centres[:, None, :] + v[None, :, :]).reshape(-1, 3)
    tris = (np.arange(count)[:, None, None] * len(v) + f[None, :, :]).reshape(-1, 3)
    return points, tris


def make_inputs(folder, data):
    cases = []
    p = folder / "torus-2M.ply"
    write_binary_ply(p, *torus(2000, 500))
    cases.append(("torus-2M", p, 100_000))
    igea = data / "igea.ply"
    if igea.exists():
        cases.append(("igea-500k", igea, 500_000))
    else:
        print(f"scale.py: {igea} not found; igea-500k skipped", file=sys.stderr)
    p = folder / "10k-components.ply"
    write_binary_ply(p, *icosahedra(10_000))
    cases.append(("10k-components", p, 120_000))
    p = folder / "one-triangle.ply"
    write_binary_ply(p, np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float), np.array([[0, 1, 2]]))
    cases.append(("one-triangle", p, 100_000))
    return cases


def run_measured(cmd, folder, timeout):
    """Runs cmd; returns (exit code or None on timeout, stdout, stderr, wall s, peak RSS MB).
    The child is spawned and reaped here with wait4, which gives its own peak memory."""
    out_path, err_path = folder / "stdout.txt", folder / "stderr.txt"
    start = time.monotonic()
    with open(out_path, "w") as out, open(err_path, "w") as err:
        pid = os.posix_spawn(cmd[0], cmd, os.environ, file_actions=[
            (os.POSIX_SPAWN_DUP2, out.fileno(), 1), (os.POSIX_SPAWN_DUP2, err.fileno(), 2)])
    while True:
        rpid, status, usage = os.wait4(pid, os.WNOHANG)
        if rpid:
            break
        if time.monotonic() - start > timeout:
            os.kill(pid, 9)
            os.wait4(pid, 0)
            return None, "", "", timeout, 0.0
        time.sleep(0.05)
    wall = time.monotonic() - start
    return (os.waitstatus_to_exitcode(status), out_path.read_text(), err_path.read_text(), wall,
            usage.ru_maxrss / 1024.0)


def triangles_of(exe, mesh):
    q = subprocess.run([exe, "quality", str(mesh), "--json"], capture_output=True, text=True)
    return json.loads(q.stdout)["faces"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=str(ROOT / "build"))
    ap.add_argument("--data", default=str(ROOT.parent / "shared" / "data"))
    ap.add_argument("--only", default="")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--timeout", type=float, default=3600)
    args = ap.parse_args()
    exe = str(Path(args.build) / "apps" / "cvtmesh" / "cvtmesh")
    only = set(filter(None, args.only.split(",")))
    print("| case | input triangles | vertices | time (s) | peak memory (MB) | bound (MB) | "
          "peak / bound | manifold | same topology | θmin (°) | Qmin |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for name, mesh, n in make_inputs(tmp, Path(args.data)):
            if only and name not in only:
                continue
            triangles = triangles_of(exe, mesh)
            out = tmp / f"{name}-out.ply"
            cmd = [exe, "remesh", str(mesh), str(out), "--vertices", str(n), "--json",
                   "--no-hausdorff", "--quiet", "--threads", str(args.threads)]
            code, stdout, stderr, wall, peak_mb = run_measured(cmd, tmp, args.timeout)
            if code is None:
                print(f"| {name} | {triangles} | {n} | timeout | | | | | | | |")
                continue
            bound_mb = (200 * triangles + 300 * n) / 2**20
            if code != 0:
                print(f"| {name} | {triangles} | {n} | {wall:.1f} | {peak_mb:.0f} | {bound_mb:.0f} "
                      f"| | failed: {stderr.strip().splitlines()[-1]} | | | |")
                continue
            j = json.loads(stdout)
            manifold = j["nonmanifold_edges"] == 0 and j["nonmanifold_vertices"] == 0
            print(f"| {name} | {triangles:,} | {j['vertices']:,} | {wall:.1f} | {peak_mb:.0f} | "
                  f"{bound_mb:.0f} | {peak_mb / bound_mb:.2f} | {'yes' if manifold else 'NO'} | "
                  f"{'yes' if j.get('same_topology', True) else 'no'} | "
                  f"{j['angle_min_deg']:.1f} | {j['q_min']:.3f} |", flush=True)


if __name__ == "__main__":
    main()
