#!/usr/bin/env python3
"""Robustness fuzz: remesh damaged copies of the shared meshes and check every output's validity.

Each round takes every mesh of ../shared/data and ../shared/data/corpus (OFF and OBJ), rotates,
scales (10^-3 to 10^3) and moves it at random, damages it as the round's number says, and
remeshes it with the defaults at a random count (300, 1.5k, 4k or 9k), with --adaptive on about a
third of the runs, another --seed on half, one thread on a third:

    round % 7 == 0   noise: every vertex moved by 5% of the median edge length
    round % 7 == 1   dropouts: 1% of the triangles removed, apart from one another and from the
                     boundary (each a hole of one triangle; the input stays a manifold)
    round % 7 == 2   both, milder: noise of 2%, 0.3% of the triangles removed
    round % 7 == 3   a soup, as a vision pipeline or an STL export gives: every face with
                     vertices of its own, one face in ten turned the other way
    round % 7 == 4   slivers, as a CAD tessellation has: 3% of the edges inside the surface
                     split at a point 0.2-2% of their length from one end (each of the edge's
                     two triangles in two: a needle and a sliver), the surface unchanged
    round % 7 == 5   holes: three discs removed, each the triangles at a vertex and its
                     neighbours (about 20, under a tenth of the mesh), apart from one another
                     and from the boundary
    round % 7 == 6   squashed: scaled by 0.05-0.3 along a random direction, nothing else
                     (every part a thin plate, sheets closer than the spacing: still embedded,
                     so its output must be too)

(Until 2026-12-05 the kinds went by round % 3: rounds 3, 4 and 5 that earlier notes cite were
noise, dropouts and both; until 2026-12-07 by round % 6, round 6 was noise.)

A run fails when cvtmesh exits with an error, when the output has non-manifold edges or vertices
where the input has none or a triangle of no area (an angle under 0.001°), when its topology
(components, Euler characteristic, boundary loops) differs from the input's (a soup's also when
it differs from that of the copy it was made from, repaired, where that is a manifold: the
repair must stitch it back; checked without --options), or when its triangles pass through one
another away from where the input's do (the report's output_crossing_triangles; since
2026-12-07). Runs over --slow seconds are listed
too. The same round always makes the same inputs and options (a mesh's randomness depends on
the round and its place in the full list, not on --only), so a failure is reproduced by its
round and name; --keep DIR keeps the failing inputs there.

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
    """A moved, scaled and rotated copy, with this round's damage; and for a soup, the copy as
    it was before (the mesh its repair should give back), else None."""
    rotation, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    scale = 10 ** rng.uniform(-3, 3)
    shift = rng.normal(size=3) * scale * rng.uniform(0, 100)
    mode = round_number % 7
    points = vertices @ rotation.T
    if mode == 6:
        points[:, 2] *= rng.uniform(0.05, 0.3)
    points = points * scale + shift
    triangles = np.array([f[:3] for f in faces if len(f) >= 3])
    edge = np.median(np.linalg.norm(points[triangles[:, 0]] - points[triangles[:, 1]], axis=1))
    noise = {0: 0.05, 2: 0.02}.get(mode, 0.0)
    if noise > 0:
        points = points + rng.normal(size=points.shape) * noise * edge
    uses = {}
    for f in faces:
        for k in range(len(f)):
            e = tuple(sorted((f[k], f[(k + 1) % len(f)])))
            uses[e] = uses.get(e, 0) + 1
    # Vertices on the boundary or a non-manifold edge: no damage touches them.
    touched = {v for e, n in uses.items() if n != 2 for v in e}
    rate = {1: 0.01, 2: 0.003}.get(mode, 0.0)
    if rate > 0:
        kept = []
        for f, draw in zip(faces, rng.random(len(faces))):
            if draw < rate and len(f) == 3 and not touched.intersection(f):
                touched.update(f)  # each hole's too: no two holes touch
            else:
                kept.append(f)
        faces = kept
    whole = None
    if mode == 3:
        whole = points, faces
        soup, points_of = [], []
        for f, turned in zip(faces, rng.random(len(faces)) < 0.1):
            first = len(points_of)
            points_of.extend(f)
            soup.append(list(range(first, first + len(f)))[::-1 if turned else 1])
        points, faces = points[points_of], soup
    if mode == 4:
        points, faces = split_edges(points, faces, uses, touched, rng)
    if mode == 5:
        faces = cut_discs(faces, touched, rng)
    return points, faces, whole


def split_edges(points, faces, uses, touched, rng):
    """Mode 4's points and faces: 3% of the edges between two triangles split near an end, no
    triangle split twice."""
    by_edge = {}
    for i, f in enumerate(faces):
        if len(f) == 3:
            for k in range(3):
                by_edge.setdefault(tuple(sorted((f[k], f[(k + 1) % 3]))), []).append(i)
    points = list(points)
    split = set()
    out = [list(f) for f in faces]
    for (a, b), pair in by_edge.items():
        if len(pair) != 2 or uses[(a, b)] != 2 or split.intersection(pair) or rng.random() >= 0.03:
            continue
        if a in touched and b in touched:
            continue
        t = rng.uniform(0.002, 0.02)
        p = len(points)
        points.append(points[a] + t * (points[b] - points[a]))
        for i in pair:
            f = faces[i]
            k = next(k for k in range(3) if {f[k], f[(k + 1) % 3]} == {a, b})
            u, v, w = f[k], f[(k + 1) % 3], f[(k + 2) % 3]
            out[i] = [u, p, w]
            out.append([p, v, w])
        split.update(pair)
    return np.array(points), out


def cut_discs(faces, touched, rng):
    """Mode 5's faces: three discs of triangles removed, each the triangles at a random vertex
    and its neighbours, apart from one another and from `touched`."""
    around = {}
    for i, f in enumerate(faces):
        for v in f:
            around.setdefault(v, []).append(i)
    neighbours = {v: {w for i in ts for w in faces[i]} for v, ts in around.items()}
    vertices = list(around)
    gone, discs = set(), 0
    for pick in rng.permutation(len(vertices))[:200]:
        disc = {i for w in neighbours[vertices[pick]] for i in around[w]}
        corners = {w for i in disc for w in faces[i]}
        # A disc of a tenth of the faces or more is no hole but most of a small mesh (a cube's).
        if (touched.intersection(corners) or any(len(faces[i]) != 3 for i in disc)
                or 10 * len(disc) >= len(faces)):
            continue
        gone.update(disc)
        # Its corners and one ring more: the next disc stays apart from this one.
        touched.update(w for c in corners for w in neighbours[c])
        discs += 1
        if discs == 3:
            break
    return [f for i, f in enumerate(faces) if i not in gone]


def write_off(path, points, faces):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        out.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in points)
        out.writelines(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in faces)


def quality(cli, path):
    r = subprocess.run([cli, "quality", str(path), "--json"], capture_output=True, text=True)
    return json.loads(r.stdout) if r.returncode == 0 else {}


def stitched_back(cli, whole, tmp, report):
    """Whether a soup's output (`report`) has the topology of the mesh it was made of (`whole`:
    points and faces), repaired; true where that is not a manifold (a soup of it has no edge of
    three triangles to keep)."""
    given, repaired = Path(tmp) / "whole.off", Path(tmp) / "repaired.off"
    write_off(given, *whole)
    subprocess.run([cli, "repair", str(given), str(repaired)], capture_output=True, text=True)
    q = quality(cli, repaired)
    if q.get("nonmanifold_edges", 0) or q.get("nonmanifold_vertices", 0):
        return True
    keys = ("components", "euler_characteristic", "boundary_loops")
    return all(q.get(k) == report[k] for k in keys)


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
                points, faces, whole = damaged(*read_polygons(mesh), round_number, rng)
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
                    elif not report["same_topology"] or (
                            whole is not None and not args.options
                            and not stitched_back(cli, whole, tmp, report)):
                        problem = (f"topology: {report['components']} components, Euler "
                                   f"characteristic {report['euler_characteristic']}, "
                                   f"{report['boundary_loops']} loops")
                    elif report["output_crossing_triangles"] > 0:
                        problem = (f"{report['output_crossing_triangles']} triangles pass through "
                                   "others away from the input's crossings")
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
