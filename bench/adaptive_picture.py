#!/usr/bin/env python3
"""The README's picture of adaptive remeshing (issue 20): one mesh remeshed to the same vertex
count uniformly and with --adaptive, drawn side by side as wireframes from the same camera by
the project's own report (cvtmesh.report), with each one's figures in its title.

    PYTHONPATH=build/python /usr/bin/python3 bench/adaptive_picture.py MESH OUT.png
        [--vertices 2000] [--elevation E] [--azimuth A]

Needs the Python module (build/python) and matplotlib (Debian's python3-matplotlib).
"""

import argparse
import io

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

import cvtmesh  # noqa: E402
from cvtmesh.report import Camera, Mesh, view  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("mesh")
    p.add_argument("out")
    p.add_argument("--vertices", type=int, default=2000)
    p.add_argument("--elevation", type=float, default=20.0)
    p.add_argument("--azimuth", type=float, default=-60.0)
    a = p.parse_args()

    V, F = cvtmesh.read(a.mesh)
    camera = Camera(np.asarray(V), a.elevation, a.azimuth)
    figure = plt.figure(figsize=(8.4, 4.6), dpi=100)
    for column, adaptive in enumerate((None, 1.5)):
        V2, F2, r = cvtmesh.remesh(V, F, vertices=a.vertices, adaptive=adaptive)
        picture = view(Mesh(np.asarray(V2), np.asarray(F2), cvtmesh.quality(V2, F2)), camera,
                       "wireframe")
        ax = figure.add_axes([column * 0.5, 0, 0.5, 0.9])
        ax.imshow(mpimg.imread(io.BytesIO(picture), format="png"))
        ax.set_axis_off()
        name = "uniform" if adaptive is None else f"--adaptive {adaptive}"
        ax.set_title(f"{name}: {len(V2)} vertices, θmin {r['angle_min_deg']:.1f}°, "
                     f"Hausdorff max {r['hausdorff_max_pct']:.2f}%\n"
                     f"topology {'kept' if r['same_topology'] else 'LOST'}, "
                     f"{r['seeds_added']} seeds added", fontsize=9)
    figure.savefig(a.out)


if __name__ == "__main__":
    main()
