"""cvtmesh: isotropic surface remeshing by centroidal Voronoi tessellation, on numpy arrays.

    import cvtmesh
    V, F = cvtmesh.read("examples/knot1.off")
    V2, F2, report = cvtmesh.remesh(V, F, vertices=3000)
    print(report["q_min"], report["angle_min_deg"], report["same_topology"])
    cvtmesh.write("knot-3k.off", V2, F2)

Functions: remesh, read, write, quality, triangle_shapes, features, lfs, rvd, keep_freed_memory
(see help() of each). Arrays in:
(n, 3) float vertex coordinates and (m, 3) int triangles. Arrays out: float64 and int32,
handed over without copies. Reports are dicts with the keys of the CLI's --json.

Modules run with `python3 -m`: cvtmesh.report (an HTML page of a remesh, to look at) and
cvtmesh.batch (a folder of meshes, on a process pool or a Dask cluster).
"""

from ._cvtmesh import (  # noqa: F401  (the package's API)
    RemeshProgress,
    __version__,
    features,
    keep_freed_memory,
    lfs,
    quality,
    read,
    remesh,
    rvd,
    triangle_shapes,
    write,
)

__all__ = ["remesh", "read", "write", "quality", "triangle_shapes", "features", "lfs", "rvd",
           "keep_freed_memory", "RemeshProgress", "__version__"]
