// cvtmesh.quality, cvtmesh.features and cvtmesh.rvd: what the CLI's `quality` and `rvd`
// commands measure, on numpy arrays.
#include <tbb/global_control.h>

#include <cmath>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/features.hpp"
#include "cvtmesh/hausdorff.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/report.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "cvtmesh/sizing.hpp"

namespace cvtmesh::python {

namespace {

std::optional<tbb::global_control> thread_limit(int threads) {
  if (threads < 0) throw InvalidArgument("threads must not be negative (0: all cores)");
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
  return limit;
}

py::dict quality(const py::object& V, const py::object& F, const py::object& ref,
                 std::size_t samples, int threads) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  std::optional<TriangleMesh> reference;
  if (!ref.is_none()) {
    const auto pair = ref.cast<py::tuple>();
    if (pair.size() != 2) throw InvalidArgument("ref: expected a (V, F) pair");
    reference = mesh_from_arrays(pair[0], pair[1]);
  }
  std::optional<MeshReport> report;
  {
    py::gil_scoped_release released;
    const auto limit = thread_limit(threads);
    std::optional<HausdorffReport> distance;
    if (reference) distance = hausdorff_distance(mesh, *reference, {.samples = samples});
    report = report_mesh("mesh", mesh, reference ? &*reference : nullptr,
                         distance ? &*distance : nullptr);
  }
  return to_python(report->json);
}

py::dict triangle_shapes(const py::object& V, const py::object& F) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  std::vector<double> q(mesh.triangles.size()), smallest(q.size()), largest(q.size());
  for (std::size_t t = 0; t < q.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const TriangleShape s = triangle_shape(a, b, c);
    q[t] = s.quality, smallest[t] = s.min_angle, largest[t] = s.max_angle;
  }
  py::dict d;
  d["q"] = to_numpy(std::move(q));
  d["min_angle_deg"] = to_numpy(std::move(smallest));
  d["max_angle_deg"] = to_numpy(std::move(largest));
  return d;
}

py::dict features(const py::object& V, const py::object& F, double angle, double scale,
                  const py::object& feature_edges) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  FeatureSettings settings;
  settings.angle_deg = angle;
  settings.scale = scale;  // 0: every curve of sharp edges, as an explicit --feature-angle
  if (!feature_edges.is_none())
    settings.user_edges = edges_from_array(feature_edges, mesh.vertices.size());
  Features found;
  double narrowest = 0;
  {
    py::gil_scoped_release released;
    found = detect_features(mesh, settings);
    narrowest = narrowest_feature_sector_deg(mesh, found);
  }
  py::list curves, closed;
  for (FeatureCurve& c : found.curves) {
    closed.append(c.closed);
    curves.append(to_numpy(std::move(c.vertices)));
  }
  py::dict d;
  d["edges"] = to_numpy(std::move(found.edges));
  d["corners"] = to_numpy(std::move(found.corners));
  d["curves"] = curves;
  d["closed"] = closed;
  d["narrowest_sector_deg"] = narrowest;
  return d;
}

py::array_t<double> lfs(const py::object& V, const py::object& F, double gradation,
                        std::size_t samples, std::uint64_t seed, bool sharp, double scale,
                        int threads) {
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  std::vector<double> sizes;
  {
    py::gil_scoped_release released;
    const auto limit = thread_limit(threads);
    FeatureSettings detection;
    detection.sharp_edges = sharp;
    detection.scale = scale;
    const Features features = detect_features(mesh, detection);
    sizes = local_feature_size(
        mesh, {.samples = samples, .seed = seed, .gradation = gradation, .features = &features});
  }
  return to_numpy(std::move(sizes));
}

py::dict rvd(const py::object& V, const py::object& F, const py::object& seed_array, bool rdt,
             int threads) {
  TriangleMesh mesh = mesh_from_arrays(V, F);
  std::vector<Vec3> seeds = points_from_array(seed_array, "seeds");
  if (const RepairReport r = repair_mesh(mesh); r.noteworthy())
    PyErr_WarnEx(PyExc_UserWarning, ("cvtmesh.rvd: repaired: " + r.summary()).c_str(), 1);
  if (mesh.triangles.empty()) throw InputError("F: no triangle of non-zero area");
  // As `cvtmesh rvd`: spatially sorted (short walks) and at about unit size (no overflow);
  // the per-seed figures do not depend on either, and are scaled back.
  const int e = size_exponent(mesh);
  mesh = scaled_by_power_of_two(spatially_sorted(mesh).mesh, -e);
  for (Vec3& p : seeds) p = scaled_by_power_of_two(p, -e);

  std::optional<CellIntegrals> integrals;
  std::vector<Triangle> triangles;
  TraversalStats stats;
  {
    py::gil_scoped_release released;
    const auto limit = thread_limit(threads);
    const RestrictedVoronoiDiagram diagram(mesh, std::move(seeds));
    CellIntegrator integrator(diagram);
    RestrictedDelaunayBuilder builder(diagram);
    std::vector<PolygonSink*> sinks{&integrator};
    if (rdt) sinks.push_back(&builder);
    stats = diagram.traverse(sinks);
    integrals = integrator.result();
    triangles = builder.result().triangles;
  }
  const std::size_t n = integrals->mass.size();
  std::vector<double> area(n), energy(n);
  std::vector<Vec3> centroid(n);
  for (std::size_t i = 0; i < n; ++i) {
    area[i] = std::ldexp(integrals->mass[i], 2 * e);
    energy[i] = std::ldexp(integrals->energy[i], 4 * e);
    centroid[i] = integrals->mass[i] > 0
                      ? scaled_by_power_of_two(integrals->centroid(static_cast<Index>(i)), e)
                      : Vec3{NAN, NAN, NAN};
  }
  py::dict d;
  d["areas"] = to_numpy(std::move(area));
  d["centroids"] = to_numpy(std::move(centroid));
  d["energies"] = to_numpy(std::move(energy));
  d["energy"] = std::ldexp(integrals->total_energy, 4 * e);
  d["surface_area"] = std::ldexp(surface_area(mesh), 2 * e);
  d["polygons"] = stats.polygons;
  d["predicates"] = stats.predicates;
  d["exact_fallbacks"] = stats.exact_fallbacks;
  d["perturbed_ties"] = stats.perturbed_ties;
  if (rdt) d["rdt"] = to_numpy(std::move(triangles));
  return d;
}

}  // namespace

void add_measures(py::module_& m) {
  m.def("quality", &quality, py::arg("V"), py::arg("F"), py::arg("ref") = py::none(), py::kw_only(),
        py::arg("samples") = 0, py::arg("threads") = 0,
        R"(Counts, topology and triangle quality of a mesh: `cvtmesh quality [--ref]`.

ref : (V, F) pair, optional
    A reference mesh: adds the two-sided Hausdorff distance (as % of the reference's
    bounding-box diagonal) and the topology comparison.
samples : int, default 0
    Hausdorff samples per surface besides all vertices; 0: max(200k, 2 x faces), at most 1M.
threads : int, default 0 (all cores)

Returns a dict with the keys of `cvtmesh quality --json`: q_min, angle_min_deg (degrees),
pct_angle_below_30, hausdorff_max_pct, same_topology, ...)");
  m.def("triangle_shapes", &triangle_shapes, py::arg("V"), py::arg("F"),
        R"(The shape of every triangle, as `quality` measures it.

Returns a dict of (m,) float64 arrays: "q" (Q = 6/sqrt(3) A/(p h), paper section 5: 1 for
an equilateral triangle, 0 for a degenerate one), "min_angle_deg" and "max_angle_deg".)");
  m.def("features", &features, py::arg("V"), py::arg("F"), py::arg("angle") = 60.0, py::kw_only(),
        py::arg("scale") = 0.0, py::arg("feature_edges") = py::none(),
        R"(Sharp edges, boundaries and corners of a mesh (paper section 4.3).

angle : float, degrees, default 60
    An interior edge is sharp when its two faces' normals differ by more than this.
    Boundary and non-manifold edges are features always.
scale : float, default 0
    An output's target edge length: curves of sharp edges only are then dropped where they
    are no features at that scale (shorter than twice it, jagged folds between sides that
    are not flat within it, folds amid an input that bends at its own resolution, creases
    free at both ends shorter than 8 times it or than a third of their component across,
    creases that leave an end along a boundary edge with under 30 degrees of surface
    between them, or the longer of two curves joining the same corners within half of
    it), as remesh does by default. 0 keeps every curve.
feature_edges : (k, 2) int array, optional
    More feature edges, as vertex-id pairs; each must be an edge of the mesh.

Returns a dict: "edges" (k, 2) int32 (smaller id first, sorted), "corners" int32 vertex ids,
"curves" (a list of int32 arrays of vertex ids, corner to corner), "closed" (per curve: a loop
without corners) and "narrowest_sector_deg" (the narrowest angle between two feature edges at
a vertex, which bounds any faithful output's smallest angle; 360 when none).)");
  const LfsSettings lfs_defaults;
  m.def("lfs", &lfs, py::arg("V"), py::arg("F"), py::kw_only(),
        py::arg("gradation") = lfs_defaults.gradation, py::arg("samples") = lfs_defaults.samples,
        py::arg("seed") = lfs_defaults.seed, py::arg("features") = true, py::arg("scale") = 0.0,
        py::arg("threads") = 0,
        R"(Local feature size at each vertex (paper section 4.1): `cvtmesh lfs`.

The distance to the nearest pole (Amenta-Bern) of the vertices' 3D Delaunay triangulation,
in the mesh's units (0 for a vertex used by no triangle), as an (n,) float64 array. Near
sharp features and boundaries, no more than the gap across which another part of them faces
the vertex (a strip's width, a small hole's).

gradation : float, default 1.5
    The sizes change by at most 1/gradation per unit length along edges; 0: raw estimate.
samples : int, default 0
    Area samples added to the vertices, for a coarse mesh whose vertices are too sparse for
    its thin parts (they make every edge of the polyhedron a feature).
seed : int, default 1
    Of those samples.
features : bool, default True
    Sharp edges narrow the sizes too (boundaries always do), as `features()` finds them.
scale : float, default 0
    The scale of that detection (the target edge length of a remesh; 0: every curve).)");
  m.def("rvd", &rvd, py::arg("V"), py::arg("F"), py::arg("seeds"), py::kw_only(),
        py::arg("rdt") = false, py::arg("threads") = 0,
        R"(The exact restricted Voronoi diagram of seeds on a surface: `cvtmesh rvd`.

seeds : (k, 3) float array
    Distinct points (near the surface, usually on it).
rdt : bool, default False
    Also return the restricted Delaunay triangulation.

Returns a dict: per seed, "areas" (its restricted cell's area), "centroids" ((k, 3); NaN for
an empty cell) and "energies" (integral of the squared distance to the seed over its cell);
"energy" (the CVT energy, their sum), "surface_area" (the cells' areas sum to it to
round-off), "polygons", "predicates", "exact_fallbacks", "perturbed_ties"; with rdt, "rdt":
(t, 3) int32 triangles of seed indices. Raises ValueError for two identical seeds.)");
}

}  // namespace cvtmesh::python
