#!/usr/bin/env python3
"""Robustness fuzz: remesh damaged copies of the shared meshes and check every output's validity.

Each round takes every mesh of ../shared/data and ../shared/data/corpus (OFF and OBJ), rotates,
scales (10^-3 to 10^3) and moves it at random, damages it as the round's number says, and
remeshes it with the defaults at a random count (300, 1.5k, 4k or 9k), with --adaptive on about a
third of the runs, another --seed on half, one thread on a third:

    round % 3 == 0   noise: every vertex moved by 5% of the median edge length
    round % 3 == 1   dropouts: 1% of the triangles removed, apart from one another and from the
                     boundary (each a hole of one triangle; the input stays a manifold)
    round % 3 == 2   both, milder: noise of 2%, 0.3% of the triangles removed

A run fails when cvtmesh exits with an error, when the output has non-manifold edges or vertices
where the input has none or a triangle of no area (an angle under 0.001°), or when its topology
(components, Euler characteristic, boundary loops) differs from the input's. Runs over --slow
seconds are listed too. The same round always makes the same inputs and options (a mesh's
randomness depends on the round and its place in the full list, not on --only), so a failure is
reproduced by its round and name; --keep DIR keeps the failing inputs there.

    bench/fuzz.py [--rounds 0,1,2] [--only NAME,...] [--build build] [--data DIR] [--keep DIR]
                  [--timeout S] [--slow S] [--options "--fill-holes ..."]

--options adds remesh options to every run (the topology is then checked against the input as
remesh takes it: with --fill-holes, the filled input).

Exit code 1 when any run failed. Needs numpy (Debian's python3-numpy).
"""

import argparse
import json
import os
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
COUNTS = [300, 1500, 4000, 9000]
# An output triangle with an angle under this has no area to speak of, which the manifold
# guarantee (issue 18 item 1) rules out: the threshold of corpus.py's guard and of the finishing
# steps' judge (kFlatDeg in src/finish/bar_shapes.hpp).
FLAT_DEG = 1e-3


def read_polygons(path):
    """Vertices (n × 3 array) and faces (lists of indices) of an OFF or OBJ file."""
    vertices, faces = [], []
    if path.suffix == ".off":
        lines = [w for w in (line.split("#")[0].split() for line in path.read_text().splitlines())
                 if w]
        # The keyword (OFF, COFF, ...) alone on its line, or with the counts after it.
        first = 2 if len(lines[0]) == 1 else 1
        counts = lines[1] if first == 2 else lines[0][1:]
        nv, nf = int(counts[0]), int(counts[1])
        for w in lines[first:first + nv]:
            vertices.append([float(x) for x in w[:3]])
        for w in lines[first + nv:first + nv + nf]:
            faces.append([int(x) for x in w[1:1 + int(w[0])]])
    else:
        for line in path.read_text().splitlines():
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                vertices.append([float(x) for x in w[1:4]])
            elif w[0] == "f":
                faces.append([int(x.split("/")[0]) - 1 for x in w[1:]])
    return np.array(vertices), faces


def damaged(vertices, faces, round_number, rng):
    """A moved, scaled and rotated copy, with this round's damage."""
    rotation, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    scale = 10 ** rng.uniform(-3, 3)
    shift = rng.normal(size=3) * scale * rng.uniform(0, 100)
    points = vertices @ rotation.T * scale + shift
    triangles = np.array([f[:3] for f in faces if len(f) >= 3])
    edge = np.median(np.linalg.norm(points[triangles[:, 0]] - points[triangles[:, 1]], axis=1))
    mode = round_number % 3
    noise = {0: 0.05, 1: 0.0, 2: 0.02}[mode]
    if noise > 0:
        points = points + rng.normal(size=points.shape) * noise * edge
    rate = {0: 0.0, 1: 0.01, 2: 0.003}[mode]
    if rate > 0:
        uses = {}
        for f in faces:
            for k in range(len(f)):
                e = tuple(sorted((f[k], f[(k + 1) % len(f)])))
                uses[e] = uses.get(e, 0) + 1
        # Vertices on the boundary or a non-manifold edge, then each hole's: no hole touches them.
        touched = {v for e, n in uses.items() if n != 2 for v in e}
        kept = []
        for f, draw in zip(faces, rng.random(len(faces))):
            if draw < rate and len(f) == 3 and not touched.intersection(f):
                touched.update(f)
            else:
                kept.append(f)
        faces = kept
    return points, faces


def write_off(path, points, faces):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        out.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in points)
        out.writelines(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in faces)


def quality(cli, path):
    r = subprocess.run([cli, "quality", str(path), "--json"], capture_output=True, text=True)
    return json.loads(r.stdout) if r.returncode == 0 else {}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", default="0,1,2")
    parser.add_argument("--only", default="")
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--data", default=str(ROOT.parent / "shared" / "data"))
    parser.add_argument("--keep", default="")
    parser.add_argument("--timeout", type=float, default=600)
    parser.add_argument("--slow", type=float, default=20)
    parser.add_argument("--options", default="", help="remesh options added to every run")
    args = parser.parse_args()
    cli = str(Path(args.build) / "apps" / "cvtmesh" / "cvtmesh")
    data = Path(args.data)
    if not Path(cli).exists() or not data.is_dir():
        sys.exit(f"fuzz.py: needs {cli} (build first) and {data}")
    # DIR and DIR/corpus, as ../shared/data is laid out; any other folder of meshes alone.
    meshes = sorted(p for d in (data, data / "corpus") if d.is_dir() for p in d.iterdir()
                    if p.suffix in (".off", ".obj"))
    only = set(filter(None, args.only.split(",")))
    failures, slow, runs = [], [], 0
    with tempfile.TemporaryDirectory() as tmp:
        for round_number in map(int, args.rounds.split(",")):
            for index, mesh in enumerate(meshes):
                if only and mesh.stem not in only:
                    continue
                rng = np.random.default_rng(round_number * 1000 + index)
                points, faces = damaged(*read_polygons(mesh), round_number, rng)
                count = int(rng.choice(COUNTS))
                options = []
                if rng.random() < 0.3:
                    options.append("--adaptive")
                if rng.random() < 0.5:
                    options += ["--seed", str(int(rng.integers(1, 1000)))]
                if rng.random() < 0.3:
                    options += ["--threads", "1"]
                given = Path(tmp) / f"r{round_number}_{mesh.stem}.off"
                write_off(given, points, faces)
                cmd = [cli, "remesh", str(given), str(Path(tmp) / "out.off"), "--vertices",
                       str(count), "--json", "--no-hausdorff", "--quiet"] + options + shlex.split(
                           args.options)
                start = time.monotonic()
                try:
                    r = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
                    code, out, err = r.returncode, r.stdout, r.stderr
                except subprocess.TimeoutExpired:
                    code, out, err = -1, "", "timeout"
                seconds = time.monotonic() - start
                runs += 1
                what = f"round {round_number} {mesh.name} {count} {' '.join(options)}".strip()
                problem = ""
                if code != 0:
                    problem = "error: " + (err.strip().splitlines() or ["?"])[-1]
                else:
                    report = json.loads(out)
                    # A non-manifold input keeps its non-manifold edges and vertices, traced at
                    # the output's spacing: their counts differ from the input's.
                    before = quality(cli, given)
                    more_defects = ((report["nonmanifold_edges"] > 0
                                     and before.get("nonmanifold_edges", 0) == 0)
                                    or (report["nonmanifold_vertices"] > 0
                                        and before.get("nonmanifold_vertices", 0) == 0))
                    if more_defects:
                        problem = (f"non-manifold: {report['nonmanifold_edges']} edges, "
                                   f"{report['nonmanifold_vertices']} vertices")
                    elif report["angle_min_deg"] < FLAT_DEG:
                        problem = f"a triangle of no area: θmin {report['angle_min_deg']:.2g}°"
                    elif not report["same_topology"]:
                        problem = (f"topology: {report['components']} components, Euler "
                                   f"characteristic {report['euler_characteristic']}, "
                                   f"{report['boundary_loops']} loops")
                print(f"{'FAIL' if problem else 'ok  '} {what}: {seconds:.1f} s"
                      + (f"; {problem}" if problem else ""), flush=True)
                if problem:
                    failures.append((what, problem))
                    if args.keep:
                        os.makedirs(args.keep, exist_ok=True)
                        Path(args.keep, given.name).write_bytes(given.read_bytes())
                if seconds > args.slow:
                    slow.append((seconds, what))
    print(f"\n{runs} runs, {len(failures)} failed, {len(slow)} over {args.slow:g} s")
    for what, problem in failures:
        print(f"  failed: {what}: {problem}")
    for seconds, what in sorted(slow, reverse=True)[:10]:
        print(f"  slow: {what}: {seconds:.1f} s")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
