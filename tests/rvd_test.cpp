// The exact RVD: it tiles the surface, matches a brute-force reference, survives degenerate
// seed configurations, has the right gradient, yields a manifold RDT, and is deterministic.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <tuple>
#include <utility>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "cvtmesh/sampling.hpp"
#include "cvtmesh/topology.hpp"
#include "geometry/random.hpp"
#include "support/shapes.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

double polygon_area(std::span<const Vec3> p) {
  Vec3 twice{};
  for (std::size_t k = 1; k + 1 < p.size(); ++k) twice += cross(p[k] - p[0], p[k + 1] - p[0]);
  return 0.5 * norm(twice);
}

// Area of every (seed, triangle) piece.
class PieceAreas : public PolygonSink {
 public:
  void begin(std::size_t chunks) override { chunks_.assign(chunks, {}); }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    std::vector<Vec3> points;
    for (const RvdVertex& v : p.vertices) points.push_back(v.point);
    chunks_[chunk].push_back({{p.seed, p.triangle}, polygon_area(points)});
  }
  void end() override {
    for (const auto& c : chunks_)
      for (const auto& [key, area] : c) {
        EXPECT_FALSE(areas.count(key))
            << "two polygons for seed " << key.first << ", triangle " << key.second;
        areas[key] = area;
      }
  }
  std::map<std::pair<Index, Index>, double> areas;

 private:
  std::vector<std::vector<std::pair<std::pair<Index, Index>, double>>> chunks_;
};

// Checks that neighbouring cells agree on the combinatorics: every polygon edge on bisector
// (i, j) appears, reversed and with the same symbolic endpoints, in cell j's polygon of the same
// triangle. Vertices are named globally: an input corner, (edge, cells i and j) for type B,
// (cells i, j, k) for type C.
class SharedEdges : public PolygonSink {
 public:
  using Key = std::array<std::int64_t, 5>;
  void begin(std::size_t chunks) override { chunks_.assign(chunks, {}); }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    const auto& v = p.vertices;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const RvdVertex &a = v[k], &b = v[(k + 1) % v.size()];
      std::int32_t plane = -1;
      for (std::int32_t s : a.symbols)
        if (s >= 0 && (s == b.symbols[0] || s == b.symbols[1])) plane = s;
      if (plane < 0) continue;  // on an input edge: not shared inside this triangle
      chunks_[chunk].push_back(
          {p.triangle, p.seed, static_cast<Index>(plane), name(p.seed, a), name(p.seed, b)});
    }
  }
  void end() override {
    std::map<std::tuple<Index, Index, Index, Key, Key>, int> edges;
    for (const auto& c : chunks_)
      for (const Edge& e : c) ++edges[{e.triangle, e.cell, e.other, e.from, e.to}];
    for (const auto& [edge, count] : edges) {
      const auto& [t, i, j, from, to] = edge;
      EXPECT_EQ(count, 1) << "edge repeated in cell " << i;
      EXPECT_TRUE(edges.count({t, j, i, to, from}))
          << "triangle " << t << ": cell " << i << " has an edge on the bisector with " << j
          << " that cell " << j << " does not have";
      ++checked;
    }
  }
  std::size_t checked = 0;

 private:
  struct Edge {
    Index triangle, cell, other;
    Key from, to;
  };
  static Key name(Index cell, const RvdVertex& v) {
    constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
    std::array<std::int64_t, 3> cells{cell, kNone, kNone};
    std::int64_t edge = -1;
    int n = 1;
    for (std::int32_t s : v.symbols) {
      if (s >= 0)
        cells[n++] = s;
      else
        edge = edge < 0 ? -s - 1 : edge * 3 + (-s - 1);
    }
    if (n == 1) return {0, edge, 0, 0, 0};  // corner: named by its two edges, in order
    std::sort(cells.begin(), cells.end());
    return {n - 1, edge, cells[0], cells[1], cells[2]};
  }
  std::vector<std::vector<Edge>> chunks_;
};

// Every triangle is covered exactly once: its pieces add up to its area, all pieces add up to
// the surface area (relative tolerance `tol`), and neighbouring cells agree (SharedEdges).
TraversalStats expect_tiling(const TriangleMesh& mesh, const std::vector<Vec3>& seeds,
                             double tol = 1e-12) {
  const RestrictedVoronoiDiagram rvd(mesh, seeds);
  PieceAreas pieces;
  CellIntegrator integrator(rvd);
  SharedEdges shared;
  PolygonSink* sinks[] = {&pieces, &integrator, &shared};
  const TraversalStats stats = rvd.traverse(sinks);
  std::vector<double> per_triangle(mesh.triangles.size(), 0);
  for (const auto& [key, area] : pieces.areas) per_triangle[key.second] += area;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    const double area = triangle_area(a, b, c);
    EXPECT_NEAR(per_triangle[t], area, tol * area + 1e-300) << "triangle " << t;
  }
  const double total = surface_area(mesh);
  EXPECT_NEAR(integrator.result().total_mass, total, tol * total);
  return stats;
}

// Issue 22: at 2^-600 triangle areas underflow; sampling works at about unit size.
TEST(Sampling, AShapeScaledByAPowerOfTwoGivesTheSameSamplesScaled) {
  const TriangleMesh m = torus(1, 0.4, 24, 12);
  const std::vector<Vec3> unit = sample_surface(m, 100, 3);
  for (const int k : {-600, -20, 20, 600}) {
    const std::vector<Vec3> points = sample_surface(scaled_by_power_of_two(m, k), 100, 3);
    ASSERT_EQ(points.size(), unit.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      EXPECT_EQ(points[i], scaled_by_power_of_two(unit[i], k)) << "2^" << k << ", sample " << i;
  }
}

TEST(Rvd, CellsTileGeneratedSurfaces) {
  for (const TriangleMesh& m : {icosphere(3), torus(2, 0.5, 40, 20), cube(4), disk(6, 24)}) {
    expect_tiling(m, sample_surface(m, 300, 7));
  }
}

TEST(Rvd, CellsTileARandomTriangleSoup) {
  TriangleMesh soup;
  CounterRng rng(3, 0);
  for (int t = 0; t < 300; ++t) {
    for (int k = 0; k < 3; ++k)
      soup.vertices.push_back({rng.uniform(), rng.uniform(), rng.uniform()});
    const Index b = static_cast<Index>(3 * t);
    soup.triangles.push_back({b, b + 1, b + 2});
  }
  expect_tiling(soup, sample_surface(soup, 200, 1), 1e-11);
}

TEST(Rvd, ZeroAreaTrianglesAreSkipped) {
  TriangleMesh m = icosphere(2);
  const Index v = static_cast<Index>(m.vertices.size());
  m.vertices.push_back({0.25, 0.5, 0.75});
  m.vertices.push_back({0.5, 1.0, 1.5});
  m.triangles.push_back({0, 0, 1});      // repeated corner
  m.triangles.push_back({v, v + 1, 2});  // not collinear: kept
  m.vertices.push_back({1.0, 2.0, 3.0});
  m.triangles.push_back({v, v + 1, v + 2});  // exactly collinear
  expect_tiling(m, sample_surface(m, 100, 2));
}

// O(n·m) reference: each triangle clipped against each cell by every other seed's bisector,
// in plain doubles (fine for random, non-degenerate seeds).
std::map<std::pair<Index, Index>, double> brute_force(const TriangleMesh& mesh,
                                                      const std::vector<Vec3>& seeds) {
  std::map<std::pair<Index, Index>, double> areas;
  for (Index t = 0; t < mesh.triangles.size(); ++t) {
    for (Index i = 0; i < seeds.size(); ++i) {
      const auto c = mesh.corners(t);
      std::vector<Vec3> poly(c.begin(), c.end());
      for (Index j = 0; j < seeds.size() && !poly.empty(); ++j) {
        if (j == i) continue;
        auto side = [&](const Vec3& p) {
          return dot(seeds[j] - seeds[i], (p - seeds[i]) + (p - seeds[j]));
        };
        std::vector<Vec3> out;
        for (std::size_t k = 0; k < poly.size(); ++k) {
          const Vec3 &a = poly[k], &b = poly[(k + 1) % poly.size()];
          const double sa = side(a), sb = side(b);
          if (sa < 0) out.push_back(a);
          if ((sa < 0) != (sb < 0)) out.push_back(a + (sa / (sa - sb)) * (b - a));
        }
        poly = out;
      }
      if (poly.size() >= 3) areas[{i, t}] = polygon_area(poly);
    }
  }
  return areas;
}

TEST(Rvd, MatchesBruteForceReference) {
  const TriangleMesh m = torus(1, 0.35, 16, 8);
  const std::vector<Vec3> seeds = sample_surface(m, 60, 11);
  const RestrictedVoronoiDiagram rvd(m, seeds);
  PieceAreas pieces;
  rvd.traverse(pieces);
  const auto reference = brute_force(m, seeds);
  const double scale = surface_area(m) / static_cast<double>(m.triangles.size());
  for (const auto& [key, area] : reference) {
    const auto it = pieces.areas.find(key);
    if (it == pieces.areas.end()) {
      EXPECT_LT(area, 1e-12 * scale)
          << "missing piece of seed " << key.first << ", triangle " << key.second;
      continue;
    }
    EXPECT_NEAR(it->second, area, 1e-12 * scale)
        << "seed " << key.first << ", triangle " << key.second;
  }
  for (const auto& [key, area] : pieces.areas)
    if (!reference.count(key)) {
      EXPECT_LT(area, 1e-12 * scale) << "extra piece";
    }
  EXPECT_GT(pieces.areas.size(), m.triangles.size());
}

// Graded seeds on a coarse input: the sparse seeds' cells reach past their stored nearest seeds
// (crowded by the dense ones) and span several input triangles, so their radius searches are
// asked again on each, with reaches that differ (Impl::for_candidates reuses a search's seeds
// within its reach only). Every piece is the brute-force one.
TEST(Rvd, GradedSeedsOnCoarseTrianglesMatchBruteForce) {
  const TriangleMesh m = icosphere(0);  // 20 triangles
  std::vector<Vec3> seeds = sample_surface(m, 40, 4);
  for (const Vec3& p : sample_surface(m, 400, 5))
    if (p.z > 0.5) seeds.push_back(p);  // dense near one pole
  const RestrictedVoronoiDiagram rvd(m, seeds);
  PieceAreas pieces;
  const TraversalStats stats = rvd.traverse(pieces);
  EXPECT_GT(stats.radius_searches, 0u);
  const auto reference = brute_force(m, seeds);
  const double scale = surface_area(m) / static_cast<double>(m.triangles.size());
  std::size_t compared = 0;
  for (const auto& [key, area] : reference) {
    const auto it = pieces.areas.find(key);
    const double got = it == pieces.areas.end() ? 0.0 : it->second;
    EXPECT_NEAR(got, area, 1e-12 * scale) << "seed " << key.first << ", triangle " << key.second;
    ++compared;
  }
  for (const auto& [key, area] : pieces.areas)
    if (!reference.count(key)) {
      EXPECT_LT(area, 1e-12 * scale) << "extra piece";
    }
  EXPECT_GT(compared, m.triangles.size());
}

TEST(RvdDegenerate, SeedsOnARegularGridAtMeshVertices) {
  const TriangleMesh m = cube(4);  // vertices on a grid; cube corners are cospherical
  const TraversalStats stats = expect_tiling(m, m.vertices);
  EXPECT_GT(stats.perturbed_ties, 0u);  // the perturbation, not luck, decided the ties
}

TEST(RvdDegenerate, SeedsJustOffMeshVertices) {
  // Seeds at random vertices of a torus, scaled by 1.001: near-ties everywhere, where some
  // crossings' rounded positions bend a polygon a little; its fan integrals, with signed areas,
  // still sum to the cell's area from whichever vertex the fan starts.
  const TriangleMesh m = torus(1, 0.4, 48, 24);
  for (std::uint64_t draw = 0; draw < 3; ++draw) {
    // 300 of its vertices, drawn without repeats.
    std::vector<Index> ids(m.vertices.size());
    std::iota(ids.begin(), ids.end(), Index{0});
    CounterRng random(draw, 0);
    for (std::size_t k = 0; k < 300; ++k)
      std::swap(ids[k], ids[k + static_cast<std::size_t>(random.uniform() *
                                                         static_cast<double>(ids.size() - k))]);
    std::vector<Vec3> seeds;
    for (std::size_t k = 0; k < 300; ++k) seeds.push_back(1.001 * m.vertices[ids[k]]);
    SCOPED_TRACE(draw);
    expect_tiling(m, seeds);
  }
}

TEST(RvdDegenerate, SeedsExactlyOnMeshEdges) {
  const TriangleMesh m = cube(4);
  std::vector<Vec3> seeds;
  for (const Triangle& t : m.triangles)
    seeds.push_back(0.5 * (m.vertices[t[0]] + m.vertices[t[1]]));
  std::sort(seeds.begin(), seeds.end(), [](const Vec3& a, const Vec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  });
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  EXPECT_GT(expect_tiling(m, seeds).perturbed_ties, 0u);
}

TEST(RvdDegenerate, CosphericalSeeds) {
  // The 12 icosahedron vertices (cospherical) and the 8 cube corners, on a sphere and a cube.
  expect_tiling(icosphere(2), icosphere(0).vertices);
  expect_tiling(icosphere(2), cube(1).vertices);
  EXPECT_GT(expect_tiling(cube(3), cube(1).vertices).perturbed_ties, 0u);
}

TEST(RvdDegenerate, AllSeedsCoplanar) {
  const TriangleMesh flat = disk(5, 16);
  expect_tiling(flat, sample_surface(flat, 50, 3));  // in the surface's own plane
  std::vector<Vec3> ring;
  for (int k = 0; k < 10; ++k) ring.push_back({std::cos(k * 0.6), std::sin(k * 0.6), 0});
  expect_tiling(icosphere(3), ring);  // cospherical and coplanar at once
}

TEST(RvdDegenerate, SingleSeedOwnsTheWholeSurface) {
  const TriangleMesh m = torus(1, 0.3, 12, 6);
  const RestrictedVoronoiDiagram rvd(m, {{0.1, 0.2, 0.3}});
  CellIntegrator integrator(rvd);
  rvd.traverse(integrator);
  EXPECT_NEAR(integrator.result().mass[0], surface_area(m), 1e-12 * surface_area(m));
}

TEST(RvdDegenerate, FarMoreSeedsThanTriangles) {
  const TriangleMesh m = icosphere(1);  // 80 triangles
  expect_tiling(m, sample_surface(m, 8000, 5), 1e-11);
}

// A coarse input (issue 19: 3torus.off, 46 triangles, took 82× geogram's time): each triangle
// is thousands of cells wide, so a cell queued for a triangle it does not meet costs a clip of
// the whole triangle and a search over every seed near it. Only cells that meet the triangle
// are clipped: the empty clippings stay a small fraction of the polygons.
TEST(RvdCost, CoarseTrianglesClipOnlyTheCellsThatMeetThem) {
  for (const TriangleMesh& m : {torus(1, 0.35, 8, 4), cube(1), icosphere(0)}) {
    const RestrictedVoronoiDiagram rvd(m, sample_surface(m, 5000, 3));
    CellIntegrator integrator(rvd);
    const TraversalStats stats = rvd.traverse(integrator);
    EXPECT_NEAR(integrator.result().total_mass, surface_area(m), 1e-12 * surface_area(m));
    EXPECT_LE(stats.cells_clipped, stats.polygons + stats.polygons / 100)
        << m.triangles.size() << " triangles";
  }
}

TEST(RvdDegenerate, DuplicateSeedsAreRejectedWithTheirIndices) {
  const TriangleMesh m = icosphere(1);
  std::vector<Vec3> seeds = sample_surface(m, 10, 1);
  seeds.push_back(seeds[3]);
  try {
    RestrictedVoronoiDiagram rvd(m, seeds);
    FAIL() << "duplicate seeds accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("seeds 3 and 10"), std::string::npos) << e.what();
  }
}

double energy(const TriangleMesh& m, const std::vector<Vec3>& seeds) {
  const RestrictedVoronoiDiagram rvd(m, seeds);
  CellIntegrator integrator(rvd);
  rvd.traverse(integrator);
  return integrator.result().total_energy;
}

TEST(RvdIntegrals, GradientMatchesFiniteDifferences) {
  const TriangleMesh m = icosphere(3);
  const std::vector<Vec3> seeds = sample_surface(m, 40, 2);
  const RestrictedVoronoiDiagram rvd(m, seeds);
  CellIntegrator integrator(rvd);
  rvd.traverse(integrator);
  const std::vector<Vec3> gradient = integrator.result().gradient(seeds);
  const double h = 1e-6;
  for (Index s : {0u, 7u, 23u}) {
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<Vec3> plus = seeds, minus = seeds;
      double* p = axis == 0 ? &plus[s].x : axis == 1 ? &plus[s].y : &plus[s].z;
      double* q = axis == 0 ? &minus[s].x : axis == 1 ? &minus[s].y : &minus[s].z;
      *p += h, *q -= h;
      const double numeric = (energy(m, plus) - energy(m, minus)) / (2 * h);
      EXPECT_NEAR(gradient[s][axis], numeric, 1e-5 * norm(gradient[s]) + 1e-9)
          << "seed " << s << " axis " << axis;
    }
  }
}

TEST(RvdIntegrals, LinearDensityMatchesClosedForm) {
  // ρ = 1 + z on the flat unit disk... is 1 everywhere (z = 0); use ρ = 1 + x instead:
  // ∫ρ = area (x is odd), ∫ρ x = ∫x² = π/4 for the unit disk (up to its polygonal boundary).
  const TriangleMesh m = disk(30, 120);
  std::vector<double> density;
  for (const Vec3& v : m.vertices) density.push_back(1 + 0.5 * v.x);
  const RestrictedVoronoiDiagram rvd(m, {{0, 0, 0}});
  CellIntegrator integrator(rvd, density);
  rvd.traverse(integrator);
  const CellIntegrals& r = integrator.result();
  EXPECT_NEAR(r.mass[0], surface_area(m), 1e-12);
  // Exact over the polygonal disk: Σ over triangles of ∫x ρ with ρ linear = 0.5·∫x² exactly.
  double x2 = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto [a, b, c] = m.corners(t);
    x2 += triangle_area(a, b, c) / 6 *
          (a.x * a.x + b.x * b.x + c.x * c.x + a.x * b.x + b.x * c.x + c.x * a.x);
  }
  EXPECT_NEAR(r.moment[0].x, 0.5 * x2, 1e-12);
  EXPECT_NEAR(r.moment[0].y, 0.0, 1e-12);
}

TEST(RvdIntegrals, EnergyWithALinearDensityMatchesQuadrature) {
  // ∫ρ‖x − s‖² over each cell with ρ linear over each triangle: a cubic polynomial, which the
  // degree-3 rule (the centroid, weight −27/48, and (3/5, 1/5, 1/5) and its turns, 25/48)
  // integrates exactly over each of a fine mesh's triangles, as over each of its cells' polygons.
  // Here every cell is one seed's: a single seed, so its cell is the whole surface.
  const TriangleMesh m = torus(1, 0.4, 24, 12);
  std::vector<double> rho(m.vertices.size());
  for (std::size_t v = 0; v < rho.size(); ++v)
    rho[v] = 1 + 0.5 * m.vertices[v].x + 0.25 * m.vertices[v].z * m.vertices[v].z;
  const Vec3 seed{0.3, -0.2, 0.1};
  const RestrictedVoronoiDiagram rvd(m, {seed});
  CellIntegrator integrator(rvd, rho);
  rvd.traverse(integrator);
  double expected = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const std::array<Vec3, 3> q = m.corners(t);
    const Triangle& f = m.triangles[t];
    const auto at = [&](double la, double lb, double lc) {
      const Vec3 x = la * q[0] + lb * q[1] + lc * q[2];
      const double r = la * rho[f[0]] + lb * rho[f[1]] + lc * rho[f[2]];
      return r * dot(x - seed, x - seed);
    };
    const double sum = -27.0 / 48 * at(1.0 / 3, 1.0 / 3, 1.0 / 3) +
                       25.0 / 48 * (at(0.6, 0.2, 0.2) + at(0.2, 0.6, 0.2) + at(0.2, 0.2, 0.6));
    expected += triangle_area(q[0], q[1], q[2]) * sum;
  }
  EXPECT_NEAR(integrator.result().energy[0], expected, 1e-12 * expected);
}

TEST(RvdIntegrals, UniformDensityPathMatchesTheGeneralOne) {
  // No density takes a shortcut for ρ = 1; an explicit ρ = 1 per vertex takes the general
  // formula. Both integrate the same polynomials exactly.
  const TriangleMesh m = torus(1, 0.4, 24, 12);
  const std::vector<Vec3> seeds = sample_surface(m, 60, 4);
  const RestrictedVoronoiDiagram rvd(m, seeds);
  const std::vector<double> ones(m.vertices.size(), 1.0);
  CellIntegrator uniform(rvd), general(rvd, ones);
  PolygonSink* sinks[] = {&uniform, &general};
  rvd.traverse(sinks);
  const CellIntegrals &u = uniform.result(), &g = general.result();
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    EXPECT_NEAR(u.mass[s], g.mass[s], 1e-13);
    EXPECT_NEAR(u.energy[s], g.energy[s], 1e-13);
    EXPECT_NEAR(norm(u.moment[s] - g.moment[s]), 0.0, 1e-13);
  }
  EXPECT_GT(u.total_energy, 0);
}

TEST(RvdIntegrals, StoredUnitNormalsGiveTheSameSumsBitForBit) {
  // The optimizer keeps the surface's unit normals for every evaluation; the integrals are those
  // computed with each polygon's own, with a density or without. The wrong count is refused.
  const TriangleMesh m = torus(1, 0.4, 24, 12);
  const std::vector<Vec3> seeds = sample_surface(m, 60, 4);
  const RestrictedVoronoiDiagram rvd(m, seeds);
  const std::vector<Vec3> normals = unit_normals(m);
  std::vector<double> rho(m.vertices.size());
  for (std::size_t v = 0; v < rho.size(); ++v) rho[v] = 1 + m.vertices[v].z * m.vertices[v].z;
  CellIntegrator plain(rvd), stored(rvd, {}, normals), dense(rvd, rho),
      dense_stored(rvd, rho, normals);
  PolygonSink* sinks[] = {&plain, &stored, &dense, &dense_stored};
  rvd.traverse(sinks);
  for (const auto& [a, b] : {std::pair(&plain, &stored), std::pair(&dense, &dense_stored)}) {
    EXPECT_EQ(a->result().mass, b->result().mass);
    EXPECT_EQ(a->result().energy, b->result().energy);
    EXPECT_EQ(a->result().moment, b->result().moment);
  }
  const std::vector<Vec3> too_few(normals.begin(), normals.end() - 1);
  EXPECT_THROW(CellIntegrator(rvd, {}, too_few), InvalidArgument);
}

// A few Lloyd steps (seeds to their restricted centroids) spread random seeds evenly.
std::vector<Vec3> lloyd(const TriangleMesh& m, std::vector<Vec3> seeds, int steps) {
  for (int k = 0; k < steps; ++k) {
    const RestrictedVoronoiDiagram rvd(m, seeds);
    CellIntegrator integrator(rvd);
    rvd.traverse(integrator);
    for (Index s = 0; s < seeds.size(); ++s)
      if (integrator.result().mass[s] > 0) seeds[s] = integrator.result().centroid(s);
  }
  return seeds;
}

// Six times the signed volume enclosed: positive for outward-facing triangles.
double signed_volume(const TriangleMesh& m) {
  double v = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto [a, b, c] = m.corners(t);
    v += dot(a, cross(b, c));
  }
  return v;
}

void expect_manifold_rdt(const TriangleMesh& m, std::size_t n) {
  const std::vector<Vec3> seeds = lloyd(m, sample_surface(m, n, 4), 10);
  const RestrictedVoronoiDiagram rvd(m, seeds);
  RestrictedDelaunayBuilder rdt(rvd);
  rvd.traverse(rdt);
  const TopologyReport t = analyze_topology(rdt.result());
  const TopologyReport input = analyze_topology(m);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.is_closed());
  EXPECT_TRUE(t.consistently_oriented);
  EXPECT_EQ(t.euler_characteristic, input.euler_characteristic);
  EXPECT_EQ(t.vertices, n);
  EXPECT_GT(signed_volume(m) * signed_volume(rdt.result()), 0);  // oriented like the input
  TriangleMesh flipped = m;
  for (Triangle& f : flipped.triangles) std::swap(f[1], f[2]);
  const RestrictedVoronoiDiagram flipped_rvd(flipped, seeds);
  RestrictedDelaunayBuilder flipped_rdt(flipped_rvd);
  flipped_rvd.traverse(flipped_rdt);
  EXPECT_LT(signed_volume(flipped) * signed_volume(rdt.result()), 0);
  EXPECT_GT(signed_volume(flipped) * signed_volume(flipped_rdt.result()), 0);
}

TEST(RestrictedDelaunay, WellSampledSphereIsAClosedManifoldOfTheSameTopology) {
  expect_manifold_rdt(icosphere(4), 1000);
}

TEST(RestrictedDelaunay, WellSampledTorusIsAClosedManifoldOfTheSameTopology) {
  expect_manifold_rdt(torus(1, 0.4, 80, 32), 1500);
}

// Every polygon as its vertices' symbols and points, by (seed, triangle), each rotated to start at
// its smallest vertex (clipping by the same bisectors in another order may start elsewhere).
class PolygonRecord : public PolygonSink {
 public:
  using Vertex = std::tuple<std::array<std::int32_t, 2>, double, double, double>;
  void begin(std::size_t chunks) override { chunks_.assign(chunks, {}); }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    std::vector<Vertex> v;
    for (const RvdVertex& x : p.vertices)
      v.emplace_back(x.symbols, x.point.x, x.point.y, x.point.z);
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    chunks_[chunk].push_back({{p.seed, p.triangle}, v});
  }
  void end() override {
    for (const auto& c : chunks_)
      for (const auto& [key, v] : c) polygons[key] = v;
  }
  std::map<std::pair<Index, Index>, std::vector<Vertex>> polygons;

 private:
  std::vector<std::vector<std::pair<std::pair<Index, Index>, std::vector<Vertex>>>> chunks_;
};

TEST(Rvd, ANeighborCacheGivesTheSameDiagramAsAFreshSearch) {
  // Seeds moved step by step, as an optimization moves them: small steps keep the cached
  // lists (re-sorted, their complete radii shrunk), a large one makes a fresh search; the
  // polygons are the same as without the cache every time.
  const TriangleMesh m = torus(1, 0.4, 96, 40);
  std::vector<Vec3> seeds = sample_surface(m, 1500, 4);
  const double spacing = std::sqrt(4 * std::numbers::pi * std::numbers::pi * 0.4 / 1500);
  NeighborCache cache;
  CounterRng random(11, 0);
  const auto jitter = [&] { return 2 * random.uniform() - 1; };
  int reused = 0;
  for (const double step : {0.0, 0.02, 0.02, 0.05, 0.02, 1.0, 0.01, 0.01}) {
    for (Vec3& p : seeds) p += step * spacing * Vec3{jitter(), jitter(), jitter()};
    if (step == 0.01) {
      // And a few seeds jump across several cells, as a seed snapped onto a feature does: the
      // lists they leave and join are bounded by where they are now.
      for (std::size_t s = 0; s < seeds.size(); s += 151)
        seeds[s] = seeds[(s * 7 + 500) % seeds.size()] +
                   0.1 * spacing * Vec3{jitter(), jitter(), jitter()};
    }
    PolygonRecord fresh, cached;
    const RestrictedVoronoiDiagram searched(m, seeds), with_cache(m, seeds, cache);
    CellIntegrator fresh_integrals(searched), cached_integrals(with_cache);
    PolygonSink* fresh_sinks[] = {&fresh, &fresh_integrals};
    PolygonSink* cached_sinks[] = {&cached, &cached_integrals};
    searched.traverse(fresh_sinks);
    with_cache.traverse(cached_sinks);
    // The same polygons (the same start, so the same sums) to the last bit.
    EXPECT_EQ(fresh_integrals.result().energy, cached_integrals.result().energy) << step;
    EXPECT_EQ(fresh_integrals.result().mass, cached_integrals.result().mass) << step;
    reused += with_cache.build_times().neighbors_reused;
    EXPECT_EQ(with_cache.build_times().neighbors_reused, step > 0 && step < 0.5) << "step " << step;
    ASSERT_EQ(fresh.polygons.size(), cached.polygons.size()) << "step " << step;
    EXPECT_TRUE(fresh.polygons == cached.polygons) << "step " << step;
  }
  EXPECT_EQ(reused, 6);
}

// Exact predicates on exactly scaled inputs decide alike: the cells of a surface and seeds scaled
// by 2^k have the same polygons, symbol for symbol, far beyond unit size (where squared and
// fourth powers of the coordinates overflow or underflow, and filters must hand over to exact
// arithmetic rather than decide on rounded nothings).
TEST(Rvd, ScaledByAPowerOfTwoGivesTheSameCells) {
  const TriangleMesh m = torus(1, 0.4, 24, 12);
  const std::vector<Vec3> seeds = sample_surface(m, 150, 5);
  const auto symbols = [](const TriangleMesh& mesh, const std::vector<Vec3>& at) {
    PolygonRecord record;
    const RestrictedVoronoiDiagram rvd(mesh, at);
    rvd.traverse(record);
    std::map<std::pair<Index, Index>, std::vector<std::array<std::int32_t, 2>>> out;
    for (const auto& [key, vertices] : record.polygons)
      for (const auto& v : vertices) out[key].push_back(std::get<0>(v));
    return out;
  };
  const auto unit = symbols(m, seeds);
  for (const int k : {-300, -250, -70, 70, 250, 300}) {
    std::vector<Vec3> scaled_seeds;
    for (const Vec3& p : seeds) scaled_seeds.push_back(scaled_by_power_of_two(p, k));
    EXPECT_TRUE(symbols(scaled_by_power_of_two(m, k), scaled_seeds) == unit) << "2^" << k;
  }
}

TEST(Rvd, ResultsDoNotDependOnThreadCount) {
  const TriangleMesh m = torus(1, 0.4, 120, 48);  // 11,520 triangles: many chunks
  const std::vector<Vec3> seeds = sample_surface(m, 2000, 9);
  auto run = [&] {
    const RestrictedVoronoiDiagram rvd(m, seeds);
    CellIntegrator integrator(rvd);
    RestrictedDelaunayBuilder rdt(rvd);
    PolygonSink* sinks[] = {&integrator, &rdt};
    rvd.traverse(sinks);
    return std::pair(integrator.result(), rdt.result());
  };
  std::pair<CellIntegrals, TriangleMesh> one;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = run();
  }
  const auto all = run();
  EXPECT_EQ(one.first.mass, all.first.mass);
  EXPECT_EQ(one.first.energy, all.first.energy);
  EXPECT_EQ(one.first.total_energy, all.first.total_energy);
  for (std::size_t s = 0; s < seeds.size(); ++s)
    ASSERT_EQ(one.first.moment[s], all.first.moment[s]);
  EXPECT_EQ(one.second.triangles, all.second.triangles);
}

// Every polygon with its chunk, whole, and when each chunk was said to be done: for replaying
// a traversal to another sink in another order.
class ChunkLog : public PolygonSink {
 public:
  struct Kept {
    Index seed, triangle;
    std::vector<RvdVertex> vertices;
  };
  void begin(std::size_t chunks) override {
    chunks_.assign(chunks, {});
    done_.assign(chunks, 0);
  }
  void polygon(std::size_t chunk, const RvdPolygon& p) override {
    if (done_[chunk]) late_ = true;
    chunks_[chunk].push_back({p.seed, p.triangle, {p.vertices.begin(), p.vertices.end()}});
  }
  void chunk_done(std::size_t chunk) override { ++done_[chunk]; }
  // Gives the polygons of the chunks in `order` to `sink`, each chunk done after its polygons
  // when `report_done`.
  void replay(PolygonSink& sink, const std::vector<std::size_t>& order, bool report_done) const {
    sink.begin(chunks_.size());
    for (const std::size_t chunk : order) {
      for (const Kept& k : chunks_[chunk]) sink.polygon(chunk, {k.seed, k.triangle, k.vertices});
      if (report_done) sink.chunk_done(chunk);
    }
    sink.end();
  }
  std::size_t chunks() const { return chunks_.size(); }
  const std::vector<int>& done() const { return done_; }
  bool polygon_after_done() const { return late_; }

 private:
  std::vector<std::vector<Kept>> chunks_;
  std::vector<int> done_;  // per chunk: a chunk's calls all come on one thread
  std::atomic<bool> late_ = false;
};

TEST(Rvd, SaysEachChunkDoneOnceAfterItsPolygons) {
  const TriangleMesh m = torus(1, 0.4, 120, 48);
  const RestrictedVoronoiDiagram rvd(m, sample_surface(m, 2000, 9));
  ChunkLog log;
  rvd.traverse(log);
  ASSERT_GT(log.chunks(), 4u);
  EXPECT_EQ(log.done(), std::vector<int>(log.chunks(), 1));
  EXPECT_FALSE(log.polygon_after_done());
}

// CellIntegrator adds each chunk's sums as soon as the chunks before it are done, and frees it:
// the sums must be those of the chunks added in order, whatever order they finish in, and
// whether or not the chunks are said to be done before end().
TEST(CellIntegrator, AddsTheChunksInOrderWhateverOrderTheyFinishIn) {
  const TriangleMesh m = torus(1, 0.4, 120, 48);
  const RestrictedVoronoiDiagram rvd(m, sample_surface(m, 2000, 9));
  ChunkLog log;
  CellIntegrator traversed(rvd);
  PolygonSink* sinks[] = {&log, &traversed};
  rvd.traverse(sinks);
  std::vector<std::size_t> forward(log.chunks()), backward, shuffled;
  std::iota(forward.begin(), forward.end(), std::size_t{0});
  backward.assign(forward.rbegin(), forward.rend());
  shuffled = forward;
  CounterRng random(3, 0);
  for (std::size_t i = shuffled.size(); i > 1; --i)
    std::swap(shuffled[i - 1], shuffled[static_cast<std::size_t>(random.uniform() * i) % i]);
  for (const auto& order : {forward, backward, shuffled}) {
    for (const bool report_done : {true, false}) {
      CellIntegrator replayed(rvd);
      log.replay(replayed, order, report_done);
      const CellIntegrals &a = traversed.result(), &b = replayed.result();
      EXPECT_EQ(a.mass, b.mass);
      EXPECT_EQ(a.energy, b.energy);
      EXPECT_EQ(a.total_energy, b.total_energy);
      EXPECT_EQ(a.total_mass, b.total_mass);
      ASSERT_EQ(a.moment.size(), b.moment.size());
      for (std::size_t s = 0; s < a.moment.size(); ++s) ASSERT_EQ(a.moment[s], b.moment[s]) << s;
    }
  }
}

}  // namespace
}  // namespace cvtmesh
