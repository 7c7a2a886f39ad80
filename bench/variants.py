#!/usr/bin/python3
"""Variants of the shared meshes that nobody tuned to (issue 18: the product is judged on meshes
it never saw): every mesh of ../shared/data and ../shared/data/corpus, turned by a random rotation
and stretched along the rotated axes, written as OFF into OUT_DIR (and OUT_DIR/corpus), laid out
as --data expects, so that the corpus benchmark runs on them:

    bench/variants.py OUT_DIR [--stretch 2.5,1,0.4] [--seed 7] [--data DIR] [--build build]
    bench/corpus.py --data OUT_DIR --counts 2000,5000 --no-vorpalite

Stretching makes thin parts thinner and flat parts narrower than in the file, where topology
control is tested hardest. Reads and writes through the Python module (build/python), with
Debian's python3 and numpy.
"""

import argparse
import os
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
MESH_EXTS = {".off", ".obj", ".ply", ".stl"}


def random_rotation(rng):
    """A rotation matrix from a random unit quaternion."""
    q = rng.normal(size=4)
    a, b, c, d = q / np.linalg.norm(q)
    return np.array([
        [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
        [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
        [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d]])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("out", type=Path)
    p.add_argument("--stretch", default="2.5,1,0.4", help="factors along the rotated x, y, z")
    p.add_argument("--seed", type=int, default=7)
    p.add_argument("--data", default=os.environ.get("CVTMESH_SHARED_DATA",
                                                    str(ROOT.parent / "shared" / "data")))
    p.add_argument("--build", default=str(ROOT / "build"))
    a = p.parse_args()
    sys.path.insert(0, str(Path(a.build) / "python"))
    import cvtmesh  # noqa: E402

    stretch = np.array([float(s) for s in a.stretch.split(",")])
    if stretch.shape != (3,) or not np.all(stretch > 0):
        sys.exit("--stretch: three positive factors, comma-separated")
    rng = np.random.default_rng(a.seed)
    data = Path(a.data)
    if not data.is_dir():
        sys.exit(f"{data}: not a directory (set --data or CVTMESH_SHARED_DATA)")
    written = 0
    for folder, into in ((data, a.out), (data / "corpus", a.out / "corpus")):
        if not folder.is_dir():
            continue
        into.mkdir(parents=True, exist_ok=True)
        for mesh in sorted(f for f in folder.iterdir() if f.suffix.lower() in MESH_EXTS):
            vertices, triangles = cvtmesh.read(str(mesh))
            turned = (vertices @ random_rotation(rng).T) * stretch
            cvtmesh.write(str(into / (mesh.stem + ".off")), turned, triangles)
            written += 1
    print(f"{written} meshes written to {a.out}")


if __name__ == "__main__":
    main()
