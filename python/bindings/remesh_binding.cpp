// cvtmesh.remesh: the `cvtmesh remesh` command on numpy arrays, with the same options under the
// same names, returning the same report as its --json.
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "cvtmesh/allocator.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/report.hpp"
#include "cvtmesh/sampling.hpp"
#include "python_hooks.hpp"

namespace cvtmesh::python {

namespace {

template <class T>
bool given(const std::optional<T>& value) {
  return value.has_value();
}

Optimizer optimizer_named(const std::string& name) {
  if (name == "lbfgs") return Optimizer::lbfgs;
  if (name == "lloyd") return Optimizer::lloyd;
  throw InvalidArgument("optimizer: '" + name + "' is not one of lbfgs, lloyd");
}

CvtMode mode_named(const std::string& name) {
  if (name == "both") return CvtMode::both;
  if (name == "rcvt") return CvtMode::rcvt;
  if (name == "ccvt") return CvtMode::ccvt;
  throw InvalidArgument("mode: '" + name + "' is not one of rcvt, ccvt, both");
}

// Feature edges as a file name (read as `--feature-edges` reads it) or a (k, 2) array.
std::vector<Edge> feature_edges_from(const py::object& edges, std::size_t vertex_count) {
  if (py::isinstance<py::str>(edges) || py::hasattr(edges, "__fspath__"))
    return read_feature_edges(py::str(edges).cast<std::string>());
  return edges_from_array(edges, vertex_count);
}

// Target edge lengths per vertex of V: a file (as `--sizing` reads it), an array, or a function
// of a point called on each row of V.
std::vector<double> sizing_from(const py::object& sizing, const py::object& V,
                                std::size_t vertex_count) {
  std::vector<double> lengths;
  const py::module_ numpy = py::module_::import("numpy");
  if (py::isinstance<py::str>(sizing) || py::hasattr(sizing, "__fspath__")) {
    lengths = read_vertex_values(py::str(sizing).cast<std::string>());
  } else if (PyCallable_Check(sizing.ptr())) {
    for (const py::handle row : numpy.attr("asarray")(V, "float64"))
      lengths.push_back(sizing(row).cast<double>());
  } else {
    lengths = numpy.attr("asarray")(sizing, "float64").attr("ravel")().cast<std::vector<double>>();
  }
  if (lengths.size() != vertex_count)
    throw InvalidArgument("sizing: " + std::to_string(lengths.size()) + " values for " +
                          std::to_string(vertex_count) + " vertices");
  return lengths;
}

py::tuple remesh(const py::object& V, const py::object& F, std::optional<std::size_t> vertices,
                 std::optional<double> edge_length, std::optional<double> edge_length_rel,
                 const py::object& seeds, const std::optional<std::string>& seeds_file,
                 int iterations, std::size_t samples, bool no_hausdorff, int polish_rounds,
                 int shape_sweeps, int fit_rounds, int topology_rounds,
                 const std::string& optimizer, const std::string& mode, std::uint64_t seed,
                 std::optional<double> feature_angle, bool no_features,
                 const py::object& feature_edges, std::optional<double> adaptive,
                 const py::object& sizing, double gap_gradation, double min_edge_length,
                 double max_edge_length, std::optional<double> fill_holes, double time_limit,
                 bool quiet, int threads,
                 const std::function<void(const RemeshProgress&)>& progress) {
  TriangleMesh input = mesh_from_arrays(V, F);
  RemeshSettings s;
  std::vector<Edge> edges;  // in the ids of V
  if (!feature_edges.is_none()) edges = feature_edges_from(feature_edges, input.vertices.size());
  std::vector<double> lengths;  // per vertex of V
  if (!sizing.is_none()) lengths = sizing_from(sizing, V, input.vertices.size());
  std::vector<Index> new_id;  // the ids of V in the repaired mesh
  if (const RepairReport r = repair_mesh(input, &new_id); r.noteworthy())
    PyErr_WarnEx(PyExc_UserWarning, ("cvtmesh.remesh: repaired: " + r.summary()).c_str(), 1);
  try {
    s.features.user_edges = edges_after_repair(edges, new_id);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("feature_edges: ") + e.what());
  }

  if (adaptive && !sizing.is_none())
    throw InvalidArgument("adaptive and sizing exclude each other");
  s.sizing.adaptive = adaptive.value_or(0);
  if (!sizing.is_none())
    s.sizing.edge_lengths = values_after_repair(lengths, new_id, input.vertices.size());
  if (!(gap_gradation >= 0)) throw InvalidArgument("gap_gradation must not be negative");
  s.sizing.gap_gradation = gap_gradation;
  s.sizing.min_edge_length = min_edge_length;
  s.sizing.max_edge_length = max_edge_length;
  const int sizes = given(vertices) + given(edge_length) + given(edge_length_rel) +
                    !seeds.is_none() + given(seeds_file);
  if (sizes > 1 || (sizes == 0 && sizing.is_none()))
    throw InvalidArgument(
        "give exactly one of vertices, edge_length, edge_length_rel, seeds, seeds_file (or a "
        "sizing alone)");
  if (vertices) s.vertices = *vertices;
  if (edge_length) s.edge_length = *edge_length;
  if (edge_length_rel) s.edge_length_rel = *edge_length_rel;
  if (!seeds.is_none()) s.initial_seeds = points_from_array(seeds, "seeds");
  if (seeds_file) s.initial_seeds = read_points(*seeds_file);
  if (!s.initial_seeds.empty()) s.vertices = s.initial_seeds.size();  // the output size

  if (feature_angle && no_features)
    throw InvalidArgument("feature_angle and no_features exclude each other");
  s.features.sharp_edges = !no_features;
  s.features.angle_deg = feature_angle.value_or(s.features.angle_deg);
  s.features.creases_at_scale = !feature_angle;  // an explicit angle forces its creases
  s.iterations = iterations;
  s.polish_rounds = polish_rounds;
  s.shape_sweeps = shape_sweeps;
  s.fit_rounds = fit_rounds;
  s.topology_rounds = topology_rounds;
  s.optimizer = optimizer_named(optimizer);
  s.mode = mode_named(mode);
  s.seed = seed;
  s.time_limit = time_limit;
  if (!no_hausdorff) s.hausdorff = HausdorffSettings{.samples = samples};
  HoleFilling filled;
  if (fill_holes) {
    if (!(*fill_holes > 0))
      throw InvalidArgument("fill_holes must be a positive number of edge lengths");
    filled = cvtmesh::fill_holes(input, *fill_holes * requested_edge_length(input, s));
  }
  if (threads < 0) throw InvalidArgument("threads must not be negative (0: all cores)");

  PythonHooks hooks;
  s.cancel = [&hooks] { return hooks.cancel_requested(); };
  if (progress || !quiet)
    s.progress = [&](const RemeshProgress& p) {
      hooks.with_gil([&] {
        if (!quiet) py::module_::import("sys").attr("stderr").attr("write")(progress_line(p));
        if (progress) progress(p);
      });
    };

  std::optional<RemeshResult> result;
  std::optional<MeshReport> report;
  try {
    py::gil_scoped_release released;
    std::optional<tbb::global_control> limit;
    if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, threads);
    result = cvtmesh::remesh(input, s);
    report = remesh_report("output", input, *result, filled);
  } catch (const Cancelled&) {
    hooks.raise_if_stopped();  // the Python exception that stopped the work, if one did
    throw;
  }
  return py::make_tuple(to_numpy(std::move(result->mesh.vertices)),
                        to_numpy(std::move(result->mesh.triangles)), to_python(report->json));
}

constexpr const char* kRemeshDoc = R"(Isotropic remeshing by centroidal Voronoi tessellation.

Same as `cvtmesh remesh IN OUT`, on arrays: the options have the CLI's names, with
underscores for dashes. Give exactly one size: vertices, edge_length, edge_length_rel, seeds
or seeds_file.

Parameters
----------
V : (n, 3) float array
    Input vertex coordinates, in any units.
F : (m, 3) int array
    Input triangles, as indices into V. The input is repaired as the CLI repairs it
    (exact duplicate vertices merged where that keeps the surface manifold, zero-area and
    duplicate triangles dropped), with a UserWarning saying what changed.
vertices : int
    Number of output vertices.
edge_length : float
    Target edge length, in the mesh's units.
edge_length_rel : float
    Target edge length as a fraction of the bounding-box diagonal.
seeds : (k, 3) float array
    Initial seeds instead of random ones; their count is the output size.
seeds_file : str
    The same, read from a file ("x y z" lines, or a mesh's vertices).
iterations : int, default 10
    Iteration cap of each phase (RCVT, then CCVT; half for RCVT from the spread initial seeds,
    and RCVT alone, on a surface without features, takes CCVT's too).
samples : int, default 8000
    Hausdorff samples per surface for the report (spread evenly), besides all vertices and edge
    midpoints.
no_hausdorff : bool, default False
    Skip the Hausdorff distance (its report keys are None).
polish_rounds : int, default 3
    Rounds of local Lloyd steps around badly shaped triangles (0: none).
shape_sweeps : int, default 5
    Sweeps of edge flips and vertex moves along the surface around badly shaped triangles,
    then short-edge collapses where those do not help (at most 1% of the vertices), the last
    step but one (0: none).
fit_rounds : int, default 2
    Rounds of moving surface vertices along their normals so that the input lies between them
    and their triangles' middles, last, after the vertices move onto their Voronoi cells' normal
    lines and those beside the input's untraced creases onto them; never lowers θmin or Qmin (0:
    none of it; vertices stay on the input where the sweeps left them).
topology_rounds : int, default 12
    Rounds of topology control: seeds added where the output misses feature edges or
    differs in topology; the best round is kept (0: none).
optimizer : {"lbfgs", "lloyd"}, default "lbfgs"
mode : {"both", "rcvt", "ccvt"}, default "both"
    RCVT then CCVT (RCVT alone on a surface without features and with uniform sizes), or
    only one of them.
seed : int, default 1
    Random seed of the initial sampling: same seed, same output, on any thread count.
feature_angle : float, degrees
    Sharp edge: its faces' normals differ by more than this. Given, it forces these creases;
    by default (60) only creases with flat sides at the output's scale, amid an input that
    is smooth at its own resolution, are kept.
no_features : bool, default False
    Keep no sharp edges (boundaries and feature_edges are still kept).
feature_edges : str or (k, 2) int array
    Feature edges to keep, as vertex-id pairs of the input, or a file of "a b" lines.
adaptive : float, the gradation (1.5 is a good default)
    Edge lengths that follow the local feature size: short on thin parts and tight curves,
    graded so that a length doubles over at least about this many edges. The vertex count or
    edge length (their median over the surface) sets the scale.
sizing : str, (n,) float array, or callable(point) -> float
    Target edge length per vertex of V (in V's units): an array, a function called on each
    row of V, or a file (one number a line, or a PLY with a vertex scalar). Scaled to the
    vertex count or edge length if one is given, used as it is otherwise.
gap_gradation : float, default 5
    Even sizes only (no adaptive, no sizing): edges grade down towards holes, slots and
    strips narrower than half an edge length, a length doubling over at least about this many
    edges (0: even everywhere, slivers at such gaps).
min_edge_length, max_edge_length : float, default 0 (none)
    Clamps of the target lengths of adaptive or sizing.
fill_holes : float, edge lengths (the CLI's default when given alone: 10)
    First fill the input's holes whose boundary is shorter than this many edge lengths (the
    even length of the vertex count), never a sheet's rim; the report (input_holes_filled)
    then compares with the filled input. None: every hole stays a boundary loop.
time_limit : float, seconds, default 0 (none)
    Then the optimization and the rounds stop, and the mesh of the seeds as they are is
    returned (valid; report["time_limit_reached"] says so).
quiet : bool, default True
    False prints the CLI's progress lines on sys.stderr.
threads : int, default 0 (all cores)
progress : callable(RemeshProgress), optional
    Called once per iteration, with the phase, iteration, energy, gradient_norm and
    elapsed_seconds. An exception it raises stops the remesh and is raised again here.

Returns
-------
(V2, F2, report) : (k, 3) float64 array, (t, 3) int32 array, dict
    The output mesh, and the report: the same keys as `cvtmesh remesh --json`.

Raises
------
ValueError  for a bad input mesh or settings; OSError for a file that cannot be read;
MemoryError when the job would need more memory than there is (checked first);
KeyboardInterrupt on Ctrl-C (the work stops within a fraction of a second).

The GIL is released while the library works.)";

}  // namespace

void add_remesh(py::module_& m) {
  py::class_<RemeshProgress>(m, "RemeshProgress",
                             "One iteration of cvtmesh.remesh, round of topology control or redo.")
      .def_property_readonly(
          "phase", [](const RemeshProgress& p) { return std::string(p.phase); },
          "\"rcvt\", \"ccvt\", \"ccvt-surface\" (an iteration), \"topology\" (a round that added "
          "seeds) or \"redo\" (the topology was lost: the remesh starts again)")
      .def_readonly("iteration", &RemeshProgress::iteration)
      .def_readonly("energy", &RemeshProgress::energy, "CVT energy (at unit size)")
      .def_readonly("gradient_norm", &RemeshProgress::gradient_norm)
      .def_readonly("elapsed_seconds", &RemeshProgress::elapsed_seconds)
      .def_readonly("seeds", &RemeshProgress::seeds,
                    "topology: the seeds after the round; redo: its vertex count (0: from sizes)")
      .def_readonly("defects", &RemeshProgress::defects,
                    "topology: the triangles at defects the round seeded")
      .def_property_readonly(
          "detail", [](const RemeshProgress& p) { return std::string(p.detail); },
          "redo: how the new try differs")
      .def("__repr__", [](const RemeshProgress& p) {
        return "RemeshProgress(phase='" + std::string(p.phase) +
               "', iteration=" + std::to_string(p.iteration) +
               ", energy=" + std::to_string(p.energy) + ")";
      });
  const RemeshSettings defaults;  // the library's defaults are the module's
  m.def("remesh", &remesh, kRemeshDoc, py::arg("V"), py::arg("F"), py::arg("vertices") = py::none(),
        py::arg("edge_length") = py::none(), py::kw_only(), py::arg("edge_length_rel") = py::none(),
        py::arg("seeds") = py::none(), py::arg("seeds_file") = py::none(),
        py::arg("iterations") = defaults.iterations, py::arg("samples") = kRemeshReportSamples,
        py::arg("no_hausdorff") = false, py::arg("polish_rounds") = defaults.polish_rounds,
        py::arg("shape_sweeps") = defaults.shape_sweeps,
        py::arg("fit_rounds") = defaults.fit_rounds,
        py::arg("topology_rounds") = defaults.topology_rounds, py::arg("optimizer") = "lbfgs",
        py::arg("mode") = "both", py::arg("seed") = defaults.seed,
        py::arg("feature_angle") = py::none(), py::arg("no_features") = false,
        py::arg("feature_edges") = py::none(), py::arg("adaptive") = py::none(),
        py::arg("sizing") = py::none(), py::arg("gap_gradation") = defaults.sizing.gap_gradation,
        py::arg("min_edge_length") = defaults.sizing.min_edge_length,
        py::arg("max_edge_length") = defaults.sizing.max_edge_length,
        py::arg("fill_holes") = py::none(), py::arg("time_limit") = defaults.time_limit,
        py::arg("quiet") = true, py::arg("threads") = 0, py::arg("progress") = nullptr);
  m.def("keep_freed_memory", &keep_freed_memory,
        R"(Make this process's allocator keep freed memory for reuse (glibc's mallopt): remeshes
12-14% faster at the median, peak memory at most 10% higher, for every later allocation of the process. The cvtmesh
program and cvtmesh.batch's workers call it; import cvtmesh does not.)");
}

}  // namespace cvtmesh::python
