#!/usr/bin/env python3
"""Adaptive benchmark (issue 20): every mesh of ../shared/data and ../shared/data/corpus at one
vertex count (default 2k), remeshed three ways in the same run: cvtmesh uniform (the defaults),
cvtmesh --adaptive, and, with ../shared/tools/vorpalite-iso present, geogram's vorpalite with
remesh:gradation=1 (its adaptive mode). One row per mesh and tool: manifold, same topology,
seeds added by topology control, θmin, Qmin, Hausdorff mean and max (% of the bbox diagonal,
measured afterwards by `cvtmesh quality --ref` for every tool alike), wall time.

    bench/adaptive.py [--count 2000] [--jobs J] [--seed S] [--no-vorpalite] [--only NAME,...]
                      [--build build] [--data DIR] [--timeout S] [--markdown]

It ends with the issue's totals: on how many meshes adaptive keeps the topology; the seeds it
adds against uniform's; on how many its Hausdorff max is below uniform's; on how many its θmin
is at least 26° and its Qmin at least 0.53 (away from narrow input angles); the median of its
time over uniform's, and on how many that is at most 1.3; and against vorpalite's gradation, how
often it is at least as good in θmin and in Hausdorff max, and the median time ratio. The same
totals follow for the corpus (../shared/data/corpus) alone, over which the issue sets its
targets. Runs are single-threaded, J at a time.
"""

import argparse
import os
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from corpus import (  # noqa: E402
    MESH_EXTS, add_common_arguments, fmt, jobs_for, print_header, run_cvtmesh, run_in_order,
    run_vorpalite)

TOOLS = ("uniform", "adaptive", "vorpalite-g1")


def job(args):
    tool, exe, vorpalite, mesh, n, timeout, seed, threads = args
    if tool == "vorpalite-g1":
        r = run_vorpalite(exe, vorpalite, mesh, n, timeout, ["remesh:gradation=1"], threads)
    else:
        extra = ["--seed", str(seed)] + (["--adaptive"] if tool == "adaptive" else [])
        r = run_cvtmesh(exe, mesh, n, timeout, extra, True, threads)
    r["tool"] = tool
    return r


HEADER = ["mesh", "tool", "manifold", "same topo", "seeds added", "θmin", "θmin away", "Qmin",
          "Hd mean %", "Hd max %", "time s"]


def cells(name, r):
    if "error" in r:
        return [name, r["tool"], "ERROR: " + r["error"]] + [""] * 8
    m = r["manifold"]
    return [name, r["tool"], m if m == "kept" else "yes" if m else "NO",
            "yes" if r["same_topology"] else "NO", fmt(r.get("seeds_added"), "d"),
            fmt(r["theta_min"], ".1f"), fmt(r.get("theta_min_away"), ".1f"), fmt(r["q_min"], ".3f"),
            fmt(r["hd_mean"], ".3f"), fmt(r["hd_max"], ".2f"), f'{r["time"]:.2f}']


def totals(results, names, label="", vorpalite=True):
    def ok(r):
        return r is not None and "error" not in r
    kept, hd_lower, bar, ratios, n = 0, 0, 0, [], 0
    added = {"uniform": 0, "adaptive": 0}
    vs_v = {"theta": 0, "hd": 0, "both": 0, "ratios": []}
    for name in names:
        u, a, v = (results.get((name, t)) for t in TOOLS)
        if not ok(u) or not ok(a):
            continue
        n += 1
        kept += bool(a["manifold"]) and a["same_topology"]
        hd_lower += a["hd_max"] < u["hd_max"]
        # The bar holds over triangles away from the input's narrow angles (issue 20).
        theta, q = a.get("theta_min_away"), a.get("q_min_away")
        bar += (theta if theta is not None else a["theta_min"]) >= 26 and \
            (q if q is not None else a["q_min"]) >= 0.53
        ratios.append(a["time"] / max(u["time"], 1e-9))
        added["uniform"] += u.get("seeds_added") or 0
        added["adaptive"] += a.get("seeds_added") or 0
        if ok(v):
            vs_v["both"] += 1
            vs_v["theta"] += a["theta_min"] >= v["theta_min"]
            vs_v["hd"] += a["hd_max"] <= v["hd_max"]
            vs_v["ratios"].append(a["time"] / max(v["time"], 1e-9))
    if n == 0:
        print(f"{label}no mesh measured")
        return
    within = sum(r <= 1.3 for r in ratios)
    print(f"adaptive against uniform, {label}{n} meshes: topology kept {kept}/{n}; seeds added "
          f"{added['adaptive']} against {added['uniform']}; Hausdorff max lower {hd_lower}/{n}; "
          f"θmin ≥ 26° and Qmin ≥ 0.53 {bar}/{n}; time ratio median "
          f"{statistics.median(ratios):.2f}, at most 1.3 on {within}/{n}")
    if vorpalite and vs_v["both"]:
        print(f"adaptive against vorpalite remesh:gradation=1, {vs_v['both']} meshes: θmin at "
              f"least its {vs_v['theta']}, Hausdorff max at most its {vs_v['hd']}, time ratio "
              f"median {statistics.median(vs_v['ratios']):.2f}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--count", type=int, default=2000)
    p.add_argument("--seed", type=int, default=1)
    add_common_arguments(p)
    a = p.parse_args()

    exe = str(Path(a.build) / "apps" / "cvtmesh" / "cvtmesh")
    if not os.access(exe, os.X_OK):
        sys.exit(f"adaptive.py: {exe}: not built (run ./scripts/build)")
    data = Path(a.data)
    if not data.is_dir():
        sys.exit(f"adaptive.py: {data}: no shared data; nothing to measure")
    meshes = sorted(f for d in (data, data / "corpus") if d.is_dir() for f in d.iterdir()
                    if f.suffix.lower() in MESH_EXTS)
    if a.only:
        meshes = [m for m in meshes if m.name in set(a.only.split(","))]
    vorpalite = data.parent / "tools" / "vorpalite-iso"
    tools = TOOLS if not a.no_vorpalite and os.access(vorpalite, os.X_OK) else TOOLS[:2]
    tasks = [(t, exe, str(vorpalite), m, a.count, a.timeout, a.seed, a.threads) for m in meshes
             for t in tools]

    print_header(HEADER, a.markdown)

    def show(key, r):
        row = cells(key[0], r)
        print("| " + " | ".join(row) + " |" if a.markdown else "  ".join(row))

    results = run_in_order(job, tasks, lambda t: (t[3].name, t[0]), jobs_for(a), show)
    print()
    totals(results, [m.name for m in meshes])
    # The targets are over the corpus (../shared/data/corpus) alone.
    corpus = [m.name for m in meshes if m.parent.name == "corpus"]
    if corpus and len(corpus) < len(meshes):
        totals(results, corpus, "the corpus's ", vorpalite=False)


if __name__ == "__main__":
    main()
