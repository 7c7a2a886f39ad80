#!/usr/bin/env python3
"""Independent check of `cvtmesh quality --json`.

Recomputes the counts and quality figures in plain Python, with different formulas than the
C++ code (Kahan's stable Heron formula for areas, the law of cosines for angles, a dictionary of
edges), and compares: counts exactly, real numbers to 1e-6 relative. Reads OFF and OBJ itself.
Usage: quality_reference.py CVTMESH_BINARY MESH [MESH ...]   (missing meshes are skipped)
"""
import json
import math
import os
import subprocess
import sys


def read_mesh(path):
    verts, faces = [], []
    with open(path) as f:
        if path.lower().endswith(".off"):
            tokens = [t for line in f for t in line.split("#")[0].split()]
            assert tokens[0] == "OFF"
            nv, nf = int(tokens[1]), int(tokens[2])
            pos = 4
            for _ in range(nv):
                verts.append(tuple(float(x) for x in tokens[pos:pos + 3]))
                pos += 3
            for _ in range(nf):
                n = int(tokens[pos])
                faces.append([int(t) for t in tokens[pos + 1:pos + 1 + n]])
                pos += 1 + n
        else:
            for line in f:
                parts = line.split()
                if not parts:
                    continue
                if parts[0] == "v":
                    verts.append(tuple(float(x) for x in parts[1:4]))
                elif parts[0] == "f":
                    faces.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    tris = [(p[0], p[k], p[k + 1]) for p in faces for k in range(1, len(p) - 1)]
    return verts, tris


def find(parent, x):
    while parent[x] != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x


def union(parent, a, b):
    parent[find(parent, a)] = find(parent, b)


def kahan_area(a, b, c):
    a, b, c = sorted((a, b, c), reverse=True)
    s = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c))
    return 0.25 * math.sqrt(max(s, 0.0))


def angle(opposite, s1, s2):
    if s1 == 0 or s2 == 0:
        return 0.0
    c = (s1 * s1 + s2 * s2 - opposite * opposite) / (2 * s1 * s2)
    return math.degrees(math.acos(min(1.0, max(-1.0, c))))


def reference(path):
    verts, tris = read_mesh(path)
    used = sorted({v for t in tris for v in t})
    edges = {}
    for t in tris:
        for k in range(3):
            e = tuple(sorted((t[k], t[(k + 1) % 3])))
            edges[e] = edges.get(e, 0) + 1
    parent = {v: v for v in used}
    for t in tris:
        union(parent, t[0], t[1])
        union(parent, t[0], t[2])
    bparent = {}
    for (u, w), n in edges.items():
        if n == 1:
            bparent.setdefault(u, u)
            bparent.setdefault(w, w)
            union(bparent, u, w)
    dist = lambda i, j: math.dist(verts[i], verts[j])
    qs, mins, maxs = [], [], []
    for i, j, k in tris:
        a, b, c = dist(j, k), dist(k, i), dist(i, j)
        if min(a, b, c) == 0:
            qs.append(0.0), mins.append(0.0), maxs.append(180.0)
            continue
        area = kahan_area(a, b, c)
        qs.append(6 / math.sqrt(3) * area / ((a + b + c) / 2 * max(a, b, c)))
        angles = [angle(a, b, c), angle(b, c, a), angle(c, a, b)]
        mins.append(min(angles)), maxs.append(max(angles))
    lengths = [dist(u, w) for (u, w) in edges]
    mean = sum(lengths) / len(lengths)
    return {
        "vertices": len(used),
        "faces": len(tris),
        "components": len({find(parent, v) for v in used}),
        "boundary_loops": len({find(bparent, v) for v in bparent}),
        "nonmanifold_edges": sum(1 for n in edges.values() if n > 2),
        "euler_characteristic": len(used) - len(edges) + len(tris),
        "q_min": min(qs),
        "q_avg": sum(qs) / len(qs),
        "angle_min_deg": min(mins),
        "angle_min_avg_deg": sum(mins) / len(mins),
        "angle_max_deg": max(maxs),
        "pct_angle_below_30": 100.0 * sum(1 for m in mins if m < 30) / len(mins),
        "edge_length_mean": mean,
        "edge_length_std": math.sqrt(sum((l - mean) ** 2 for l in lengths) / len(lengths)),
    }


def main():
    binary, meshes = sys.argv[1], sys.argv[2:]
    failed, passed = 0, 0
    for mesh in meshes:
        if not os.path.exists(mesh):
            print(f"skipped {mesh}: not found")
            continue
        out = subprocess.run([binary, "quality", "--json", mesh], capture_output=True, text=True)
        if out.returncode != 0:
            print(f"FAIL {mesh}: cvtmesh exited {out.returncode}: {out.stderr.strip()}")
            failed += 1
            continue
        ours, ref = json.loads(out.stdout), reference(mesh)
        mismatches = 0
        for key, expected in ref.items():
            got = ours[key]
            ok = got == expected if isinstance(expected, int) else \
                math.isclose(got, expected, rel_tol=1e-6, abs_tol=1e-9)
            if not ok:
                print(f"FAIL {mesh}: {key} = {got}, independent reference says {expected}")
                mismatches += 1
        print(f"{'ok  ' if mismatches == 0 else 'FAIL'} {mesh}")
        failed, passed = failed + (mismatches > 0), passed + (mismatches == 0)
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or passed == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
