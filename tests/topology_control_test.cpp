// Topology control of the output (paper §4.4): cells in several pieces are found, feature
// curves cut by a third cell get a seed of their own there, and the best round is kept.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <cstdio>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <random>

#include "cvt/cell_islands.hpp"
#include "cvtmesh/errors.hpp"
#include "cvtmesh/features.hpp"
#include "cvtmesh/quality.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/report.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/sampling.hpp"
#include "cvtmesh/topology.hpp"
#include "features/curve_projector.hpp"
#include "features/edge_uses.hpp"
#include "features/feature_seeds.hpp"
#include "geometry/self_crossings.hpp"
#include "geometry/surface_projector.hpp"
#include "remesh/flip_links.hpp"
#include "remesh/make_manifold.hpp"
#include "remesh/mend_topology.hpp"
#include "remesh/output_defects.hpp"
#include "remesh/pinch_defects.hpp"
#include "support/shapes.hpp"
#include "support/shared_data.hpp"
#include "voronoi/cell_pieces.hpp"
#include "voronoi/piece_euler.hpp"
#include "voronoi/side_rings.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

// The output vertices of the seeds topology control added: distinct output ids, at most one per
// seed added, and some whenever seeds were added in cells or at defects (seeds on curves may
// replace others).
void expect_added_vertices_listed(const RemeshResult& r) {
  const std::vector<Index>& added = r.vertices_added;
  EXPECT_TRUE(std::is_sorted(added.begin(), added.end()));
  EXPECT_EQ(std::adjacent_find(added.begin(), added.end()), added.end());
  for (const Index v : added) EXPECT_LT(v, r.mesh.vertices.size());
  EXPECT_LE(added.size(), r.islands_seeded + r.seeds_refined + r.links_mended);
  if (r.islands_seeded + r.seeds_refined > 0) {
    EXPECT_FALSE(added.empty());
  }
  if (r.islands_seeded + r.seeds_refined + r.links_mended == 0) {
    EXPECT_TRUE(added.empty());
  }
}

// A manifold output with the input's components, Euler characteristic and boundary loops, and no
// triangle removed by the last step.
void expect_topology_kept(const RemeshResult& r, const TriangleMesh& input) {
  const TopologyReport t = analyze_topology(r.mesh), in = analyze_topology(input);
  EXPECT_TRUE(t.is_manifold()) << t.nonmanifold_edges << " non-manifold edges, "
                               << t.nonmanifold_vertices << " vertices";
  EXPECT_TRUE(same_topology(t, in))
      << "components " << t.components << " vs " << in.components << ", χ "
      << t.euler_characteristic << " vs " << in.euler_characteristic << ", loops "
      << t.boundary_loops << " vs " << in.boundary_loops << "; " << r.triangles_removed
      << " triangles removed";
  EXPECT_EQ(r.triangles_removed, 0u);
}

// The box [-1,1]² × [-0.01,0.01]: a thin plate, closed.
TriangleMesh thin_plate() {
  TriangleMesh m = cube(8);
  for (Vec3& v : m.vertices) v.z *= 0.01;
  return m;
}

TEST(CellIslands, ASeedOverAThinPlateOwnsAPieceOfTheFarFace) {
  // One seed over the middle of the top face, eight around the bottom face's rim: the rim
  // seeds own the plate's sides, so the middle seed's cell is a piece on top and one below.
  std::vector<Vec3> seeds{{0, 0, 0.01}};
  for (int k = 0; k < 8; ++k)
    seeds.push_back({0.9 * std::cos(k * M_PI / 4), 0.9 * std::sin(k * M_PI / 4), -0.01});
  const std::vector<CellIsland> islands = cell_islands(thin_plate(), seeds);
  ASSERT_EQ(islands.size(), 1u);
  EXPECT_EQ(islands[0].seed, 0u);
  // The smaller piece is the far one, below, around the middle.
  EXPECT_DOUBLE_EQ(islands[0].centroid.z, -0.01);
  EXPECT_LT(std::abs(islands[0].centroid.x) + std::abs(islands[0].centroid.y), 0.05);
  EXPECT_GT(islands[0].area, 0.5);
}

TEST(CellIslands, WellSpreadSeedsHaveNone) {
  const TriangleMesh sphere = icosphere(4);
  std::vector<Vec3> seeds;
  for (std::size_t v = 0; v < sphere.vertices.size(); v += 7) seeds.push_back(sphere.vertices[v]);
  EXPECT_TRUE(cell_islands(sphere, seeds).empty());
  // Seeds on both faces of the plate, as dense as the plate is thin: every cell is one piece.
  std::vector<Vec3> dense;
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j < 200; ++j)
      dense.push_back({-0.995 + 0.01 * i, -0.995 + 0.01 * j, (i + j) % 2 ? 0.01 : -0.01});
  EXPECT_TRUE(cell_islands(thin_plate(), dense).empty());
}

// Three pages of a book, n × n quads each, 120° apart around the spine x = y = 0, z in [-1, 1]:
// one spine shared by all (an edge of three triangles at each step), or one copy per page.
TriangleMesh book(int n, bool shared_spine) {
  TriangleMesh m;
  const auto spine = [&] {
    const auto first = static_cast<Index>(m.vertices.size());
    for (int j = 0; j <= n; ++j) m.vertices.push_back({0, 0, -1 + 2.0 * j / n});
    return first;
  };
  const Index shared = spine();
  for (int page = 0; page < 3; ++page) {
    const Index axis = shared_spine ? shared : spine();
    const double angle = 2 * M_PI * page / 3;
    const auto first = static_cast<Index>(m.vertices.size());
    for (int i = 1; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        m.vertices.push_back({std::cos(angle) * i / n, std::sin(angle) * i / n, -1 + 2.0 * j / n});
    // Column i (0: the spine) and row j.
    const auto at = [&](int i, int j) {
      return static_cast<Index>(i == 0 ? axis + j : first + (i - 1) * (n + 1) + j);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        add_quad(m, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  }
  return m;
}

TEST(CellIslands, ACellAroundAnEdgeOfThreeSheetsIsOnePieceAndThreeWhereTheSheetsOnlyTouch) {
  // A seed near the middle of the spine, and seeds further out on every page: its cell spreads
  // onto all three pages around the spine.
  std::vector<Vec3> seeds{{0.01, 0.02, 0.03}};
  for (int page = 0; page < 3; ++page)
    for (const double z : {-0.8, 0.0, 0.8}) {
      const double angle = 2 * M_PI * page / 3;
      seeds.push_back({0.7 * std::cos(angle), 0.7 * std::sin(angle), z});
    }
  seeds.push_back({0, 0, -0.9});
  seeds.push_back({0, 0, 0.9});
  EXPECT_TRUE(cell_islands(book(12, true), seeds).empty());
  // Spine vertices copied per page: the pages touch along it, but share no edge.
  const std::vector<CellIsland> apart = cell_islands(book(12, false), seeds);
  std::size_t of_first = 0;
  for (const CellIsland& island : apart) of_first += island.seed == 0;
  EXPECT_EQ(of_first, 2u);
}

TEST(DefectSeeds, SplitCellsGetSeedsNearTheDefectsAtTheirFarthestVertices) {
  // The plate's seeds as above, the middle one's cell split, and three close together on the
  // plate's side near a corner, whose triangle stands for a defect there.
  std::vector<Vec3> seeds{{0, 0, 0.01}};
  for (int k = 0; k < 8; ++k)
    seeds.push_back({0.9 * std::cos(k * M_PI / 4), 0.9 * std::sin(k * M_PI / 4), -0.01});
  seeds.insert(seeds.end(), {{1, -0.95, 0}, {1, -0.93, 0}, {1, -0.94, 0.005}});
  const TriangleMesh plate = thin_plate();
  const Interrupt never;
  ExtractionMemory memory(plate, never);
  const std::vector<CellIsland> islands = cell_islands(plate, seeds);
  ASSERT_EQ(islands.size(), 1u);
  ASSERT_EQ(islands[0].seed, 0u);

  // Refinement near the defects: the far piece's vertex farthest from its seed, which is in the
  // seed's cell (no seed nearer) and farther from it than the piece's centroid.
  const DefectSeeds near =
      defect_seeds(plate, seeds, {{0, 1, 2}}, false, SplitCells::near_triangles, nullptr, memory);
  ASSERT_EQ(near.islands.size(), 1u);
  const Vec3 p = near.islands[0];
  EXPECT_NEAR(p.z, -0.01, 1e-12);
  for (const Vec3& s : seeds) EXPECT_LE(distance(p, seeds[0]), distance(p, s) + 1e-12);
  EXPECT_GT(distance(p, seeds[0]), distance(islands[0].centroid, seeds[0]) + 0.1);
  // Everywhere, as where no defect shows where.
  EXPECT_EQ(defect_seeds(plate, seeds, {}, false, SplitCells::farthest_everywhere, nullptr, memory)
                .islands.size(),
            1u);
  // A split cell far from the only defect is left alone.
  EXPECT_TRUE(
      defect_seeds(plate, seeds, {{9, 10, 11}}, false, SplitCells::near_triangles, nullptr, memory)
          .islands.empty());
  // None where the piece reaches a crossing of the input's sheets (here a triangle standing for
  // one, over the far piece).
  const TriangleMesh crossing{{{-0.1, -0.1, -0.01}, {0.1, -0.1, -0.01}, {0, 0.1, -0.01}},
                              {{0, 1, 2}}};
  const SurfaceProjector at(crossing);
  EXPECT_TRUE(defect_seeds(plate, seeds, {}, false, SplitCells::farthest_everywhere, &at, memory)
                  .islands.empty());
  // The paper's rule, exhaustive: every split cell, at its extra piece's centroid.
  const DefectSeeds all = defect_seeds(plate, seeds, {{9, 10, 11}}, false,
                                       SplitCells::at_centroids_everywhere, nullptr, memory);
  ASSERT_EQ(all.islands.size(), 1u);
  EXPECT_EQ(all.islands[0], islands[0].centroid);
}

// The Euler characteristic of every piece of every cell, in CellPieceCollector order.
std::vector<int> piece_eulers(const TriangleMesh& surface, const std::vector<Vec3>& seeds) {
  const RestrictedVoronoiDiagram rvd(surface, seeds);
  CellPieceCollector pieces(surface);
  PieceEulerCollector euler(surface, seeds);
  PolygonSink* sinks[] = {&pieces, &euler};
  rvd.traverse(sinks);
  std::vector<int> out;
  for (const PieceShape& shape : euler.shapes(pieces)) out.push_back(shape.euler);
  return out;
}

// The pieces of the cells of seeds between two plates closer than their spacing (each cell
// reaches both, one piece on each): per seed, largest first, each polygon's piece its own seed's,
// their areas adding up to the surface's; the same on one thread as on all (the cells are joined
// in parallel).
TEST(CellPieces, AreOrderedPerSeedAndTheSameOnAnyThreadCount) {
  const auto plate = [](double z) {
    return mapped_grid(12, 12, [z](double u, double v) { return Vec3{u, v, z}; });
  };
  const TriangleMesh plates = concatenate(plate(0), plate(0.05));
  const std::vector<Vec3> seeds = sample_surface(plates, 40, 5);
  // Each polygon's (seed, triangle), as traversed.
  struct PolygonList : PolygonSink {
    std::vector<std::vector<std::pair<Index, Index>>> chunks;
    void begin(std::size_t n) override { chunks.assign(n, {}); }
    void polygon(std::size_t chunk, const RvdPolygon& p) override {
      chunks[chunk].push_back({p.seed, p.triangle});
    }
  };
  // The pieces, and each polygon's piece; with the surface's SideRings found by the collector,
  // or given.
  const SideRings rings(plates);
  const auto pieces_on = [&](int threads, const SideRings* given) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(threads));
    const RestrictedVoronoiDiagram rvd(plates, seeds);
    CellPieceCollector pieces(plates, given);
    PolygonList list;
    PolygonSink* sinks[] = {&pieces, &list};
    rvd.traverse(sinks);
    std::vector<std::size_t> of_polygon;
    for (const auto& chunk : list.chunks)
      for (const auto& [seed, triangle] : chunk) {
        of_polygon.push_back(pieces.piece_at(seed, triangle));
        EXPECT_EQ(pieces.pieces()[of_polygon.back()].seed, seed);
      }
    return std::pair(pieces.pieces(), of_polygon);
  };
  const auto [one, one_of_polygon] = pieces_on(1, nullptr);
  const auto [all, all_of_polygon] = pieces_on(4, &rings);
  EXPECT_EQ(one_of_polygon, all_of_polygon);
  EXPECT_EQ(pieces_on(4, &rings).second, all_of_polygon);  // the rings serve again
  ASSERT_EQ(one.size(), all.size());
  double area = 0;
  std::size_t split_cells = 0;
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].seed, all[i].seed);
    EXPECT_EQ(one[i].first, all[i].first);
    EXPECT_EQ(one[i].area, all[i].area);
    EXPECT_EQ(one[i].moment, all[i].moment);
    EXPECT_EQ(one[i].largest_centre, all[i].largest_centre);
    area += one[i].area;
    if (i > 0 && one[i].seed == one[i - 1].seed) {
      EXPECT_GE(one[i - 1].area, one[i].area);
      ++split_cells;
    }
    if (i > 0) {
      EXPECT_LE(one[i - 1].seed, one[i].seed);
    }
  }
  EXPECT_NEAR(area, surface_area(plates), 1e-12 * surface_area(plates));
  EXPECT_GT(split_cells, 10u);  // most cells reach both plates
}

// Around each edge, its triangles' sides in a ring: two for an inner edge, one at a boundary,
// three where three sheets meet.
TEST(SideRings, RingTheSidesOfEachEdge) {
  TriangleMesh fan;
  fan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fan.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // three sheets on edge 0-1
  const SideRings rings(fan);
  const auto ring_of = [&](std::uint32_t side) {
    std::vector<std::uint32_t> ring{side};
    for (std::uint32_t s = rings.next(side); s != side; s = rings.next(s)) ring.push_back(s);
    std::sort(ring.begin(), ring.end());
    return ring;
  };
  EXPECT_EQ(ring_of(0), (std::vector<std::uint32_t>{0, 3, 6}));  // edge 0-1 of each
  EXPECT_EQ(ring_of(1), (std::vector<std::uint32_t>{1}));        // 1-2: a boundary
  const TriangleMesh sphere = icosphere(2);
  const SideRings closed(sphere);
  for (std::uint32_t side = 0; side < 3 * sphere.triangles.size(); ++side) {
    EXPECT_NE(closed.next(side), side);
    EXPECT_EQ(closed.next(closed.next(side)), side);
  }
}

TEST(PieceEuler, EveryCellOfWellSpreadSeedsIsADisc) {
  // Seeds on input vertices (the degenerate case: every one of them is an RVD corner).
  const TriangleMesh sphere = icosphere(4);
  std::vector<Vec3> on_vertices;
  for (std::size_t v = 0; v < sphere.vertices.size(); v += 7)
    on_vertices.push_back(sphere.vertices[v]);
  const std::vector<int> a = piece_eulers(sphere, on_vertices);
  EXPECT_EQ(a.size(), on_vertices.size());
  EXPECT_EQ(std::count(a.begin(), a.end(), 1), static_cast<std::ptrdiff_t>(a.size()));
  // Grid seeds on a grid plate (cospherical and coplanar everywhere), and cells at the boundary
  // of an open disk: discs too.
  TriangleMesh plate = cube(8);
  plate.triangles.resize(plate.triangles.size() / 6);  // one face of the cube
  std::vector<Vec3> grid;
  const std::vector<bool> used = used_vertices(plate);
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) grid.push_back(plate.vertices[v]);
  ASSERT_EQ(grid.size(), 81u);
  const std::vector<int> b = piece_eulers(plate, grid);
  EXPECT_EQ(std::count(b.begin(), b.end(), 1), static_cast<std::ptrdiff_t>(b.size()));
  const TriangleMesh open = disk(12, 48);
  const std::vector<int> c = piece_eulers(open, {{0, 0, 0}, {0.5, 0.5, 0}, {-0.7, 0.1, 0}});
  EXPECT_EQ(c, (std::vector<int>{1, 1, 1}));
}

TEST(PieceEuler, ACellAroundAHandleIsAnAnnulusAndOneCellOfAClosedSurfaceIsASphere) {
  // Tube radius 0.95 around a circle of radius 1: the hole is 0.1 across. A seed on the inner
  // equator owns the whole inside of the hole, around the axis; six on the outer equator own
  // the rest.
  std::vector<Vec3> seeds{{0.05, 0, 0}};
  for (int k = 0; k < 6; ++k)
    seeds.push_back({1.95 * std::cos(k * M_PI / 3 + 0.1), 1.95 * std::sin(k * M_PI / 3 + 0.1), 0});
  const std::vector<int> torus_cells = piece_eulers(torus(1.0, 0.95, 96, 48), seeds);
  ASSERT_EQ(torus_cells.size(), 7u);
  EXPECT_EQ(torus_cells[0], 0);
  EXPECT_EQ(std::count(torus_cells.begin() + 1, torus_cells.end(), 1), 6);
  EXPECT_EQ(piece_eulers(icosphere(3), {{0, 0, 1}}), std::vector<int>{2});
  EXPECT_EQ(piece_eulers(icosphere(3), {{0, 0, 1}, {0, 0, -1}}), (std::vector<int>{1, 1}));
}

TEST(MendMissingLinks, AStraySurfaceSeedJoinsTheCurveItCuts) {
  const TriangleMesh box = cube(4);
  const Features features = detect_features(box, {});
  ASSERT_EQ(features.corners.size(), 8u);
  const CurveProjector curves(box, features);
  // The corners, and one surface seed next to the middle of the first curve.
  std::vector<Vec3> seeds;
  SeedConstraints c;
  for (Index v : features.corners) {
    c.corner_seed.push_back(static_cast<Index>(seeds.size()));
    seeds.push_back(box.vertices[v]);
    c.kind.push_back(SeedConstraints::Kind::corner);
    c.curve.push_back(0);
    c.anchor.push_back(box.vertices[v]);
  }
  const Vec3 middle = curves.at(0, curves.length(0) / 2);
  const Vec3 inward = middle.x > 0 ? Vec3{-0.05, 0, 0} : Vec3{0.05, 0, 0};
  const Index stray = static_cast<Index>(seeds.size());
  seeds.push_back(middle + inward);
  c.kind.push_back(SeedConstraints::Kind::surface);
  c.curve.push_back(0);
  c.anchor.push_back({});

  const std::vector<FeatureLink> links = feature_links(seeds, c, features, curves);
  ASSERT_EQ(links.size(), 12u);  // one per edge of the cube, corner to corner
  const std::vector<FeatureLink> first(links.begin(), links.begin() + 1);
  ASSERT_EQ(first[0].curve, 0u);
  EXPECT_EQ(mend_missing_links(seeds, c, first, curves, CurveSpacing(0.5)), 1u);
  EXPECT_EQ(seeds.size(), 9u);  // the stray joined: no seed added
  EXPECT_EQ(c.kind.size(), 9u);
  EXPECT_EQ(c.kind[stray], SeedConstraints::Kind::curve);
  EXPECT_EQ(c.curve[stray], 0u);
  EXPECT_NEAR(norm(seeds[stray] - middle), 0.0, 1e-12);

  // Where no surface seed cuts a missing link, a new curve seed comes in at its middle if the
  // link is at least 0.9 spacings long (this one is 2), and nothing happens if it is shorter.
  const std::vector<Vec3> kept = seeds;
  EXPECT_EQ(mend_missing_links(seeds, c, {links[1]}, curves, CurveSpacing(2.5)), 0u);
  EXPECT_EQ(seeds, kept);
  EXPECT_EQ(mend_missing_links(seeds, c, {links[1]}, curves, CurveSpacing(2.0)), 1u);
  ASSERT_EQ(seeds.size(), 10u);
  ASSERT_EQ(c.kind.size(), 10u);
  EXPECT_EQ(c.kind[9], SeedConstraints::Kind::curve);
  EXPECT_EQ(c.curve[9], links[1].curve);
  const Vec3 middle_of_second = curves.at(links[1].curve, (links[1].from + links[1].to) / 2);
  EXPECT_NEAR(norm(seeds[9] - middle_of_second), 0.0, 1e-12);
  EXPECT_NEAR(norm(seeds[9] - seeds[links[1].seeds[0]]), 1.0, 1e-12);  // halfway along an edge

  // Nor does one come in where a half would still be cut: here a feature seed of another curve
  // sits next to the middle of the third link's first half, nearer to it than either end.
  const FeatureLink& third = links[2];
  const Vec3 quarter = curves.at(third.curve, third.from + (third.to - third.from) / 4);
  seeds.push_back(quarter - (0.1 / norm(quarter)) * quarter);  // towards the centre
  c.append(SeedConstraints::Kind::curve, third.curve == 0 ? 1 : 0);
  const std::vector<Vec3> cut = seeds;
  EXPECT_EQ(mend_missing_links(seeds, c, {third}, curves, CurveSpacing(1.0)), 0u);
  EXPECT_EQ(seeds, cut);
}

// Two triangles (0, 1, 3) and (3, 1, 2) of the unit square share the diagonal (1, 3).
TriangleMesh split_square() {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 3}, {3, 1, 2}};
  return m;
}

bool has_edge(const TriangleMesh& m, Index a, Index b) {
  return std::any_of(m.triangles.begin(), m.triangles.end(), [&](const Triangle& t) {
    return std::count(t.begin(), t.end(), a) + std::count(t.begin(), t.end(), b) == 2;
  });
}

TEST(FlipInLinks, OneFlipMakesTheOtherDiagonal) {
  TriangleMesh m = split_square();
  EXPECT_EQ(flip_in_links(m, {{0, 2}}, 15), std::vector<bool>{true});
  EXPECT_TRUE(has_edge(m, 0, 2));
  EXPECT_FALSE(has_edge(m, 1, 3));
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {  // still facing +z, as before
    const auto [a, b, c] = m.corners(t);
    EXPECT_GT(cross(b - a, c - a).z, 0);
  }
  EXPECT_EQ(flip_in_links(m, {{0, 2}}, 15), std::vector<bool>{false});  // there already
}

TEST(FlipInLinks, NoFlipThatFoldsMakesSliversOrIsOnANonManifoldEdge) {
  // A non-convex quad: the other diagonal runs outside it, so the flip would fold a triangle.
  TriangleMesh dart = split_square();
  dart.vertices[2] = {2, -0.5, 0};  // reflex at vertex 1
  ASSERT_GT(cross(dart.vertices[1] - dart.vertices[3], dart.vertices[2] - dart.vertices[3]).z, 0);
  EXPECT_EQ(flip_in_links(dart, {{0, 2}}, 15), std::vector<bool>{false});
  EXPECT_EQ(dart.triangles, split_square().triangles);
  // A third triangle on the diagonal: no flip there.
  TriangleMesh fin = split_square();
  fin.vertices.push_back({0.5, 0.5, 1});
  fin.triangles.push_back({1, 3, 4});
  EXPECT_EQ(flip_in_links(fin, {{0, 2}}, 15), std::vector<bool>{false});
  // A flat kite whose other diagonal is long: the flip would make 5.7° slivers.
  TriangleMesh kite;
  kite.vertices = {{0, 0, 0}, {1, -0.1, 0}, {2, 0, 0}, {1, 0.1, 0}};
  kite.triangles = {{0, 1, 3}, {3, 1, 2}};
  EXPECT_EQ(flip_in_links(kite, {{0, 2}}, 15), std::vector<bool>{false});
  // Wider, 21.8° at its long diagonal's ends: it flips only where that angle is allowed.
  kite.vertices[1] = {1, -0.4, 0};
  kite.vertices[3] = {1, 0.4, 0};
  EXPECT_EQ(flip_in_links(kite, {{0, 2}}, 30), std::vector<bool>{false});
  EXPECT_EQ(flip_in_links(kite, {{0, 2}}, 15), std::vector<bool>{true});
  // Two flips away: not this step's job.
  TriangleMesh strip;
  strip.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  strip.triangles = {{0, 1, 3}, {3, 1, 4}, {1, 2, 4}, {4, 2, 5}};
  EXPECT_EQ(flip_in_links(strip, {{0, 5}}, 15), std::vector<bool>{false});
}

// A flat 4 × 4 grid of unit squares, each split by its diagonal from (i, j) to (i + 1, j + 1):
// vertex (i, j) is 5 i + j, and the inner ones have six triangles.
TriangleMesh grid() {
  TriangleMesh m;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) m.vertices.push_back({double(i), double(j), 0});
  for (Index i = 0; i < 4; ++i)
    for (Index j = 0; j < 4; ++j) {
      const Index a = 5 * i + j, b = a + 5, c = b + 1, d = a + 1;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  return m;
}

// Whether every triangle of m faces +z (m flat in z = 0).
bool faces_up(const TriangleMesh& m) {
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto [a, b, c] = m.corners(t);
    if (!(cross(b - a, c - a).z > 0)) return false;
  }
  return true;
}

// Edge (0, 1) from a = (0, 0) to b = (b_x, 0) between triangles (0, 1, 2) and (1, 0, 3), c and d
// their third corners, with two more triangles at a and two at b (four each): a flip is allowed.
TriangleMesh butterfly(double b_x, const Vec3& c, const Vec3& d) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0},           {b_x, 0, 0},         c, d, {-0.5, 0.8, 0}, {-0.5, -0.8, 0},
                {b_x + 0.5, 0.8, 0}, {b_x + 0.5, -0.8, 0}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 2, 4}, {0, 4, 5},
                 {0, 5, 3}, {1, 6, 2}, {1, 7, 6}, {1, 3, 7}};
  return m;
}

TEST(TakeOutEdge, FlipsWhereTheFlipLeavesTheBetterAngles) {
  // c and d near the middle of a long edge: flipped, 33° at a and b; halved, 17° there.
  TriangleMesh m = butterfly(2, {1, 0.3, 0}, {1, -0.3, 0});
  ASSERT_TRUE(faces_up(m));
  EXPECT_TRUE(take_out_edge(m, {0, 1}));
  EXPECT_FALSE(has_edge(m, 0, 1));
  EXPECT_TRUE(has_edge(m, 2, 3));
  EXPECT_EQ(m.vertices.size(), butterfly(2, {}, {}).vertices.size());
  EXPECT_EQ(m.triangles.size(), butterfly(2, {}, {}).triangles.size());
  EXPECT_TRUE(faces_up(m));
  EXPECT_FALSE(take_out_edge(m, {0, 1}));  // gone already
}

TEST(TakeOutEdge, HalvesWhereTheFlipWouldLeaveAThinTriangle) {
  // c and d far above and below a: the flip would leave (c, a, d) with 169° at a (as at
  // cow.obj's pinch); halved, no angle is under 20°.
  TriangleMesh m = butterfly(1, {0.1, 1, 0}, {0.1, -1, 0});
  const TriangleMesh before = m;
  EXPECT_TRUE(take_out_edge(m, {0, 1}));
  EXPECT_FALSE(has_edge(m, 0, 1));
  EXPECT_FALSE(has_edge(m, 2, 3));
  ASSERT_EQ(m.vertices.size(), before.vertices.size() + 1);
  EXPECT_EQ(m.vertices.back(), (Vec3{0.5, 0, 0}));
  EXPECT_EQ(m.triangles.size(), before.triangles.size() + 2);
  for (const Index v : {Index{0}, Index{1}, Index{2}, Index{3}})
    EXPECT_TRUE(has_edge(m, v, static_cast<Index>(before.vertices.size())));
  EXPECT_TRUE(faces_up(m));
  EXPECT_GT(measure_quality(m).angle_min_deg, 20);
}

TEST(TakeOutEdge, HalvesWhereNoFlipMayBe) {
  // The square's diagonal: its ends have two triangles each, which a flip would leave at one.
  TriangleMesh square = split_square();
  EXPECT_TRUE(take_out_edge(square, {1, 3}));
  EXPECT_FALSE(has_edge(square, 1, 3));
  EXPECT_EQ(square.triangles.size(), 4u);
  EXPECT_TRUE(faces_up(square));
  // Edge (6, 7) of the grid lies between (1, 6, 7) and (6, 12, 7): its other diagonal is
  // (1, 12). With vertex 6 moved above that diagonal, the quad is not convex there, and
  // (1, 6, 12) would face -z.
  TriangleMesh dart = grid();
  dart.vertices[6] = {1, 1.6, 0};
  EXPECT_TRUE(take_out_edge(dart, {6, 7}));
  EXPECT_FALSE(has_edge(dart, 6, 7));
  EXPECT_FALSE(has_edge(dart, 1, 12));
  EXPECT_TRUE(faces_up(dart));
  // The other diagonal an edge already (a triangle on it, off the grid).
  TriangleMesh joined = grid();
  joined.vertices.push_back({1, 1.5, 1});
  joined.triangles.push_back({1, 12, 25});
  EXPECT_TRUE(take_out_edge(joined, {6, 7}));
  EXPECT_FALSE(has_edge(joined, 6, 7));
  EXPECT_EQ(joined.vertices.size(), grid().vertices.size() + 2);  // the off-grid one, the middle
  // An edge of one triangle (the grid's rim) or none: nothing to take out.
  TriangleMesh rim = grid();
  EXPECT_FALSE(take_out_edge(rim, {0, 1}));
  EXPECT_FALSE(take_out_edge(rim, {0, 24}));
  EXPECT_EQ(rim.triangles, grid().triangles);
}

// A boundary tip: triangle (0, 1, 2) and corner 3 past its edge (0, 1), used by no triangle.
TriangleMesh tip_with_corner_at(const Vec3& corner) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {0, 1, 0}, {-1, 0.5, 0}, corner};
  m.triangles = {{0, 1, 2}};
  return m;
}

TEST(CloseCornerTips, ACornerWithoutTrianglesGetsTheOneItsLinksBound) {
  TriangleMesh m = tip_with_corner_at({1, 0.5, 0});
  EXPECT_EQ(close_corner_wedges(m, {3}, {{0, 3}, {1, 3}}), 1u);
  ASSERT_EQ(m.triangles.size(), 2u);
  // It runs edge (0, 1) the other way round: (1, 0, 3), from whichever corner.
  Triangle added = m.triangles[1];
  std::rotate(added.begin(), std::find(added.begin(), added.end(), Index{1}), added.end());
  EXPECT_EQ(added, (Triangle{1, 0, 3}));
  EXPECT_TRUE(analyze_topology(m).is_manifold());
  EXPECT_EQ(close_corner_wedges(m, {3}, {{0, 3}, {1, 3}}), 0u);  // it has one now
}

TEST(CloseCornerTips, NoTriangleThatFoldsOrWithoutTwoLinksOrOnAnInnerEdge) {
  TriangleMesh folded = tip_with_corner_at({-2, 0.5, 0});  // on the triangle's side
  EXPECT_EQ(close_corner_wedges(folded, {3}, {{0, 3}, {1, 3}}), 0u);
  TriangleMesh one_link = tip_with_corner_at({1, 0.5, 0});
  EXPECT_EQ(close_corner_wedges(one_link, {3}, {{0, 3}}), 0u);
  TriangleMesh inner = tip_with_corner_at({1, 0.5, 0});
  inner.vertices.push_back({1, 0.5, 1});
  inner.triangles.push_back({1, 0, 4});  // edge (0, 1) has two triangles already
  EXPECT_EQ(close_corner_wedges(inner, {3}, {{0, 3}, {1, 3}}), 0u);
}

void expect_oriented_disc(const TriangleMesh& m) {
  const TopologyReport t = analyze_topology(m);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.consistently_oriented);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
}

TEST(CloseCornerTips, AWedgeOfMissingLinksIsZippedUpToTheBoundaryAcrossIt) {
  // A 6° wedge: corner 0, three seeds along each side (1-3 and 4-6), none in a triangle, and
  // the output's triangle (3, 6, 7) where it is wide enough; its edge (3, 6) is the boundary
  // across the wedge.
  TriangleMesh m;
  m.vertices = {{0, 0, 0},     {1, 0.05, 0}, {2, 0.1, 0},   {3, 0.15, 0},
                {1, -0.05, 0}, {2, -0.1, 0}, {3, -0.15, 0}, {4, 0, 0}};
  m.triangles = {{3, 6, 7}};
  const std::vector<Edge> links = {{0, 1}, {1, 2}, {2, 3}, {0, 4}, {4, 5}, {5, 6}};
  EXPECT_EQ(close_corner_wedges(m, {0}, links), 5u);
  expect_oriented_disc(m);
  EXPECT_NEAR(surface_area(m), 0.5 * 3 * 0.3 + 0.5 * 0.3 * 1, 1e-12);
  // Every link is an edge now.
  const std::vector<Edge> edges = sorted_edges(m);
  for (const Edge& e : links) EXPECT_TRUE(std::binary_search(edges.begin(), edges.end(), e));
  // The boundary across may pass a vertex of neither side: 8, whose triangles (3, 8, 7) and
  // (8, 6, 7) are the output beyond the wedge; the last triangle is (3, 8, 6).
  TriangleMesh bent = m;
  bent.triangles = {{3, 8, 7}, {8, 6, 7}};
  bent.vertices.push_back({3.1, 0, 0});
  EXPECT_EQ(close_corner_wedges(bent, {0}, links), 6u);
  expect_oriented_disc(bent);
  EXPECT_NEAR(surface_area(bent), surface_area(m), 1e-12);
  // Not past a vertex with three links.
  TriangleMesh branching = m;
  branching.triangles.resize(1);
  std::vector<Edge> three = links;
  three.push_back({2, 7});
  EXPECT_EQ(close_corner_wedges(branching, {0}, three), 0u);
}

TEST(HardCases, ASliverWithTipsOf7And10DegreesKeepsItsTips) {
  // One triangle 27 long and under 2 wide: at 500 vertices, its two tips are narrower than the
  // spacing for several spacings, where no Voronoi vertex of seeds on the two sides falls on the
  // surface. The output used to stop where it was wide enough (0 of its 2 corners; the
  // Hausdorff distance 1.8% of the diagonal).
  TriangleMesh sliver;
  sliver.vertices = {{10, 20, 30}, {1, 5, 10}, {5, 15, 21}};
  sliver.triangles = {{0, 1, 2}};
  RemeshSettings s;
  s.vertices = 500;
  s.hausdorff = HausdorffSettings{};
  const RemeshResult r = remesh(sliver, s);
  expect_topology_kept(r, sliver);
  for (const Vec3& tip : {sliver.vertices[0], sliver.vertices[1]})
    EXPECT_NE(std::find(r.mesh.vertices.begin(), r.mesh.vertices.end(), tip),
              r.mesh.vertices.end());
  ASSERT_TRUE(r.hausdorff);
  EXPECT_LT(r.hausdorff->max_pct(), 0.2);
}

// The last step's removal of defects, as a pass over the whole mesh per round of removals: the
// reference that make_manifold's local passes must match.
std::vector<Triangle> removed_by_whole_passes(TriangleMesh& mesh, bool oriented, int& passes) {
  std::vector<Triangle> removed;
  const std::vector<bool> anywhere(mesh.vertices.size(), true);
  for (passes = 0;; ++passes) {
    OutputDefects d = find_output_defects(mesh, anywhere, oriented);
    if (d.empty()) return removed;
    std::sort(d.triangles.begin(), d.triangles.end());
    const auto kept =
        std::stable_partition(mesh.triangles.begin(), mesh.triangles.end(), [&](const Triangle& t) {
          return !std::binary_search(d.triangles.begin(), d.triangles.end(), t);
        });
    removed.insert(removed.end(), kept, mesh.triangles.end());
    mesh.triangles.erase(kept, mesh.triangles.end());
  }
}

TEST(MakeManifold, RemovesWhatPassesOverTheWholeMeshRemoveAndLeavesAManifold) {
  // A sphere with random extra triangles, each on an edge of one triangle (the way that triangle
  // uses it: a fold) and a corner of another, and in a third of the cases copies of triangles
  // turned over: non-manifold edges and vertices, folds, and, once their triangles go, fans split
  // further on, pass after pass.
  const TriangleMesh sphere = icosphere(2);
  std::mt19937_64 random(5);
  int most_passes = 0;
  for (int trial = 0; trial < 40; ++trial) {
    TriangleMesh mesh = sphere;
    std::uniform_int_distribution<std::size_t> pick(0, mesh.triangles.size() - 1);
    for (int extra = 0; extra < 1 + trial % 12; ++extra) {
      const Triangle a = mesh.triangles[pick(random)], b = mesh.triangles[pick(random)];
      mesh.triangles.push_back({a[0], a[1], b[2]});
      if (trial % 3 == 0) mesh.triangles.push_back({a[1], a[0], a[2]});
    }
    for (const bool oriented : {true, false}) {
      TriangleMesh reference = mesh, local = mesh;
      int passes = 0;
      const std::vector<Triangle> expected = removed_by_whole_passes(reference, oriented, passes);
      most_passes = std::max(most_passes, passes);
      EXPECT_EQ(make_manifold(local, oriented), expected) << "trial " << trial;
      EXPECT_EQ(local.triangles, reference.triangles) << "trial " << trial;
      const std::vector<bool> anywhere(local.vertices.size(), true);
      EXPECT_TRUE(find_output_defects(local, anywhere, oriented).empty()) << "trial " << trial;
    }
  }
  EXPECT_GE(most_passes, 3);  // the cases reach past the first pass
}

// The seeds of a remesh of `box` with features, and what each is bound to (read back from where
// it lies: corners exactly, curve seeds exactly on their curve).
SeedConstraints constraints_of(const std::vector<Vec3>& seeds, const TriangleMesh& box,
                               const Features& features, const CurveProjector& curves) {
  SeedConstraints c;
  for (const Vec3& p : seeds) {
    const auto corner = std::find_if(features.corners.begin(), features.corners.end(),
                                     [&](Index v) { return box.vertices[v] == p; });
    if (corner != features.corners.end()) {
      c.append(SeedConstraints::Kind::corner, 0, p);
      continue;
    }
    std::uint32_t on = 0;
    while (on < curves.size() && norm(curves.nearest(on, p).point - p) > 1e-12) ++on;
    c.append(on < curves.size() ? SeedConstraints::Kind::curve : SeedConstraints::Kind::surface,
             on < curves.size() ? on : 0);
  }
  for (Index v : features.corners)
    c.corner_seed.push_back(
        static_cast<Index>(std::find(seeds.begin(), seeds.end(), box.vertices[v]) - seeds.begin()));
  return c;
}

TEST(TopologyControl, AStraySeedThatCutsACreaseJoinsItRatherThanAFlipMakingASliver) {
  const TriangleMesh box = cube(4);
  RemeshSettings s;
  // Whether the joined seed or the sliver flip is kept is decided by their outputs' Qmin (see
  // mend_topology): at 550 vertices the join leaves the better triangles. At 450, 500 and 650
  // (remesh's seeds as of its spread initial seeds) the flip's sliver is the lesser evil there,
  // and the flip is kept, as designed.
  s.vertices = 550;
  s.shape_sweeps = 0;  // the seeds as CVT left them, not moved by the last step
  std::vector<Vec3> seeds = remesh(box, s).mesh.vertices;
  const Features features = detect_features(box, {});
  const CurveProjector curves(box, features);
  SeedConstraints c = constraints_of(seeds, box, features, curves);
  ASSERT_TRUE(std::none_of(c.corner_seed.begin(), c.corner_seed.end(), [&](Index k) {
    return k == seeds.size();
  })) << "a corner is not a seed";
  const std::vector<FeatureLink> links = feature_links(seeds, c, features, curves);
  const SurfaceProjector projector(box);
  const CvtObjective placement(box, &projector, &c, &curves);
  const TopologyReport topology = analyze_topology(box);
  const PolishSettings polish{0, 0};
  // The scene is set up unpolished; topology control polishes as remesh does.
  const CurveSpacing spacing(0.25);
  ExtractionMemory traversals(box, placement.interrupt());
  const MendContext context{box,       topology, features, curves,    projector,
                            placement, spacing,  {},       traversals};
  // The surface seed nearest to the middle of a link moves next to it, a quarter of the link's
  // length off the crease: it cuts the link, and flipping the link in would leave 26.6°. The
  // links are tried from the middle of the list on, until one where that flip can be made.
  const std::vector<Vec3> remeshed = seeds;
  FeatureLink link{};
  Index stray = 0;
  PolishedOutput output;
  bool flippable = false;
  for (std::size_t k = 0; k < links.size() && !flippable; ++k) {
    seeds = remeshed;
    link = links[(links.size() / 2 + k) % links.size()];
    const Vec3 middle = curves.at(link.curve, (link.from + link.to) / 2);
    stray = 0;
    for (Index i = 0; i < seeds.size(); ++i)
      if (c.kind[i] == SeedConstraints::Kind::surface &&
          (c.kind[stray] != SeedConstraints::Kind::surface ||
           norm(seeds[i] - middle) < norm(seeds[stray] - middle)))
        stray = i;
    const Vec3 a = seeds[link.seeds[0]], b = seeds[link.seeds[1]];
    const Vec3 off = seeds[stray] - middle;
    const Vec3 across = off - dot(off, b - a) / dot(b - a, b - a) * (b - a);
    seeds[stray] = middle + 0.25 * norm(b - a) / norm(across) * across;
    output = extract_polished(box, seeds, placement, polish, traversals);
    // Only a flip that leaves a sliver (under 30°, at least 15°) makes it: well-shaped flips
    // are as good as moving seeds, and topology control leaves those links to them.
    TriangleMesh well_shaped = output.mesh, sliver = output.mesh;
    flippable = flip_in_links(well_shaped, {link.seeds}, 30) == std::vector<bool>{false} &&
                flip_in_links(sliver, {link.seeds}, 15) == std::vector<bool>{true};
  }
  ASSERT_TRUE(flippable) << "no link where the flip this test is about can be made";
  MendReport report;
  InputCrossings crossings(box);
  output = mend_topology(context, crossings, std::move(output), seeds, c, 3, report);
  EXPECT_EQ(c.kind[stray], SeedConstraints::Kind::curve);
  EXPECT_GE(report.links_mended, 1u);
  EXPECT_EQ(report.links_flipped, 0u);
  // The crease is traced through it.
  EXPECT_TRUE(has_edge(output.mesh, link.seeds[0], stray));
  EXPECT_TRUE(has_edge(output.mesh, stray, link.seeds[1]));
}

TEST(TopologyControl, AThinPlateComesOutHomeomorphic) {
  // A plate as thin as a quarter of the edge length: cells of seeds near its rim reach around
  // onto the other face. The ordinary restricted Delaunay triangulation is then non-manifold;
  // the multi-nerve one (a vertex per piece of a cell) has the plate's topology even without
  // rounds of topology control, and with them too.
  TriangleMesh plate = cube(8);
  for (Vec3& v : plate.vertices) v.z *= 0.05;
  RemeshSettings s;
  s.vertices = 400;
  s.features.sharp_edges = false;
  s.topology_rounds = 0;
  const RemeshResult without = remesh(plate, s);
  const TopologyReport t0 = analyze_topology(without.mesh);
  EXPECT_TRUE(t0.is_manifold());
  EXPECT_TRUE(same_topology(t0, analyze_topology(plate)));
  EXPECT_GT(without.mesh.vertices.size(), 400u);  // the far pieces' vertices
  EXPECT_EQ(without.mend_rounds, 0);

  s.topology_rounds = 3;
  const RemeshResult r = remesh(plate, s);
  const TopologyReport t = analyze_topology(r.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(same_topology(t, analyze_topology(plate)));
  EXPECT_LE(r.mesh.vertices.size(), 440u);
  // Its time is reported, as part of the extraction's (issue 18: what topology control adds).
  EXPECT_GT(r.seconds_topology, 0);
  EXPECT_LE(r.seconds_topology, r.seconds_extraction);
  s.topology_rounds = -1;
  EXPECT_THROW(remesh(plate, s), InvalidArgument);
}

TEST(TopologyControlSharedData, SelfIntersectingThinLimbsKeepTheirTopology) {
  // man.off crosses itself (848 pairs of intersecting triangles) and its limbs are thinner than
  // the edge length at 3k vertices: the ordinary restricted Delaunay triangulation had 105
  // non-manifold edges. With or without rounds of topology control the output is an oriented
  // manifold, and the rounds never leave the last step more to remove. Where the fingers run
  // through each other refinement cannot converge; with the rounds, the holes the last step
  // opens there close again and the output keeps the input's topology.
  if (!std::filesystem::exists(shared_data()))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh man = shared_mesh("man.off");
  RemeshSettings s;
  s.vertices = 3000;
  const RemeshResult controlled = remesh(man, s);
  s.topology_rounds = 0;
  const RemeshResult first = remesh(man, s);
  for (const RemeshResult* r : {&controlled, &first}) {
    const TopologyReport t = analyze_topology(r->mesh);
    EXPECT_TRUE(t.is_manifold());
    EXPECT_TRUE(t.consistently_oriented);
  }
  EXPECT_LE(controlled.triangles_removed, first.triangles_removed);
  EXPECT_TRUE(same_topology(analyze_topology(controlled.mesh), analyze_topology(man)));
  expect_added_vertices_listed(controlled);
  EXPECT_GT(controlled.vertices_added.size(), 0u);
  std::printf("man.off at 3k: %zu triangles removed without rounds, %zu with (%zu holes closed)\n",
              first.triangles_removed, controlled.triangles_removed, controlled.holes_closed);
}

TEST(TopologyControlSharedData, HandlesFarFinerThanTheSpacingAreKept) {
  // femur.off has genus 2 through handles about 0.0003 across, against an edge length of 0.026
  // at 1k vertices (0.012 at 5k). Refinement with polishing between the rounds never resolved
  // them (the output had 2 components and 7 triangles removed); the pinned rounds do. At 5k they
  // need 19 rounds, most of them no better than the best by their count of defects. At 1k with
  // seed 3 they need 32 rounds, past a cap of twice the 12 rounds. At 2.4k with seed 6 no round
  // kept them until 569c8d0, and the best by defects, its defects removed by the last step, lost
  // a handle: the best round that step rescued (holes closed) was kept instead. Since 569c8d0's
  // rounding-level changes, a round keeps them there (and at 1.8k to 3k, seeds 1 to 12).
  if (!std::filesystem::exists(shared_data()))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh femur = shared_mesh("corpus/femur.off");
  for (const auto& [count, seed] : {std::pair{1000u, 1u}, {1000u, 3u}, {5000u, 1u}}) {
    SCOPED_TRACE(::testing::Message() << count << " vertices, seed " << seed);
    RemeshSettings s;
    s.vertices = count;
    s.seed = seed;
    const RemeshResult r = remesh(femur, s);
    expect_topology_kept(r, femur);
    EXPECT_GT(r.islands_seeded + r.seeds_refined, 0u);
    expect_added_vertices_listed(r);
  }
  RemeshSettings s;
  s.vertices = 2400;
  s.seed = 6;
  const RemeshResult r = remesh(femur, s);
  const TopologyReport t = analyze_topology(r.mesh), in = analyze_topology(femur);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(same_topology(t, in)) << "components " << t.components << ", χ "
                                    << t.euler_characteristic << ", loops " << t.boundary_loops;
}

TEST(TopologyControlSharedData, CreasesThatCostTheTopologyAreDroppedAndReported) {
  // corpus/ALSTOM_TEST4.off (a CAD part: 6 open sheets) at 6k, its creases forced at 60° as
  // --feature-angle forces them: tracing 6 of its sharp edges costs the input's topology, and
  // topology wins (so from 3k to 10k). (ChineseDragon-10kv.off at 10k was this case until
  // topology control kept its 68 sharp edges too; this part at 5k until the curve seeds were
  // evened out before strays join them.)
  if (!std::filesystem::exists(shared_data()))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh part = shared_mesh("corpus/ALSTOM_TEST4.off");
  RemeshSettings s;
  s.vertices = 6000;
  s.hausdorff.reset();
  s.features.creases_at_scale = false;
  const RemeshResult r = remesh(part, s);
  expect_topology_kept(r, part);
  ASSERT_FALSE(r.feature_edges_dropped.empty());
  // What was dropped is sharp edges only: the boundary stays a feature, and none is both.
  FeatureSettings creases;
  creases.scale = 0;
  const Features all = detect_features(part, creases);
  for (const Edge& e : r.feature_edges_dropped) {
    EXPECT_TRUE(std::binary_search(all.edges.begin(), all.edges.end(), e));
    EXPECT_FALSE(std::binary_search(r.features.edges.begin(), r.features.edges.end(), e));
  }
  ASSERT_GT(analyze_topology(part).boundary_loops, 0u);
  EXPECT_FALSE(r.features.edges.empty());  // the sheets' rims
  // The remesh redone without them is topology control's time, its RCVT among it: as long as
  // the first remesh's RCVT (half the reported), give or take the machine's noise.
  EXPECT_GE(r.seconds_topology, 0.25 * r.seconds_rcvt);
  EXPECT_LE(r.seconds_topology,
            r.seconds_initialization + r.seconds_rcvt + r.seconds_ccvt + r.seconds_extraction);
}

std::size_t crossing_triangles(const TriangleMesh& mesh) {
  const std::vector<bool> crossing = self_crossing_triangles(mesh);
  return static_cast<std::size_t>(std::count(crossing.begin(), crossing.end(), true));
}

TEST(TopologyControlSharedData, CreasesThatMakeTheOutputCrossItselfAreDroppedAndReported) {
  // corpus/spool.off at 200: its creases need more seeds than the count leaves, and traced they
  // made 7 triangles pass through others (θmin 4.5°); without them, none (θmin 40.3°). The input
  // passes through itself nowhere, so neither may the output.
  if (!std::filesystem::exists(shared_data()))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh spool = shared_mesh("corpus/spool.off");
  RemeshSettings s;
  s.vertices = 200;
  s.hausdorff.reset();
  const RemeshResult r = remesh(spool, s);
  expect_topology_kept(r, spool);
  EXPECT_EQ(crossing_triangles(spool), 0u);
  EXPECT_EQ(crossing_triangles(r.mesh), 0u);
  EXPECT_EQ(r.output_crossing_triangles, 0u);
  EXPECT_FALSE(r.feature_edges_dropped.empty());
}

TEST(TopologyControlSharedData, ChordsThroughThinWallsAreHalvedUntilNoneCrosses) {
  // couplingdown.off at 100 (grown to 439, adaptive, for its genus 9): its walls between the
  // holes, about 0.02 thick, stood under edges 0.15 long, and 10 triangles sagged through the
  // wall beside them; with those edges halved, none (finish/split_crossings).
  if (!std::filesystem::exists(shared_data()))
    GTEST_SKIP() << "shared test meshes not found at " << shared_data();
  const TriangleMesh coupling = shared_mesh("couplingdown.off");
  RemeshSettings s;
  s.vertices = 100;
  s.hausdorff.reset();
  const RemeshResult r = remesh(coupling, s);
  expect_topology_kept(r, coupling);
  EXPECT_TRUE(analyze_topology(r.mesh).consistently_oriented);
  EXPECT_EQ(crossing_triangles(coupling), 0u);
  EXPECT_EQ(crossing_triangles(r.mesh), 0u);
  EXPECT_EQ(r.output_crossing_triangles, 0u);
  EXPECT_GT(r.vertices_splitting_crossings, 0u);
}

// The manifold guarantee and the input's topology (issue 18), with the defaults; and where the
// input does not pass through itself, no output triangle passes through another.
void expect_valid_remesh(const TriangleMesh& input, std::size_t vertices) {
  RemeshSettings s;
  s.vertices = vertices;
  const RemeshResult r = remesh(input, s);
  expect_topology_kept(r, input);
  EXPECT_TRUE(analyze_topology(r.mesh).consistently_oriented);
  expect_added_vertices_listed(r);
  if (crossing_triangles(input) == 0) {
    EXPECT_EQ(crossing_triangles(r.mesh), 0u);
    EXPECT_EQ(r.output_crossing_triangles, 0u);
  }
}

TEST(HardCases, TwoParallelSheetsCloserThanTheEdgeLength) {
  // Two disks 0.02 apart, edge length about 0.1: cells reach across the gap.
  expect_valid_remesh(concatenate(disk(12, 48), transformed(disk(12, 48), 1.0, {0, 0, 0.02})),
                      1000);
}

TEST(HardCases, APlateThinnerThanATenthOfTheEdgeLength) {
  // The box [-1,1]² × [-0.005,0.005]: 0.01 thick, the edge length about 0.18.
  TriangleMesh plate = cube(8);
  for (Vec3& v : plate.vertices) v.z *= 0.005;
  expect_valid_remesh(plate, 300);
}

// A closed knife whose edge is 8° or 5°, at a few hundred vertices: the spacing is many times the
// blade's thickness near its edge, and the triangles of its two sides passed through each other
// there (8° at 500 vertices: 8 crossing triangles; 5° at 300: 9), until topology control
// refined where its extractions cross themselves.
TEST(HardCases, AKnifeEdgeFarThinnerThanTheSpacingComesOutWithoutCrossings) {
  expect_valid_remesh(knife(8, 20), 500);
  expect_valid_remesh(knife(5, 20), 300);
}

// The knife of 5° with its back folded far from the edge (a vertex moved along the back past two
// of its neighbours): the input now crosses itself there (14 triangles), and the crossings at the
// edge, the output's own, are refined all the same (until this was so, no crossing was refined
// where the input crossed itself anywhere: 7 crossing triangles were left at the edge).
TEST(HardCases, AKnifeFoldedAtItsBackStillComesOutWithoutCrossingsAtItsEdge) {
  constexpr int kSteps = 20;
  TriangleMesh folded = knife(5, kSteps);
  // The middle vertex of the back (x = 1) in the middle row: ids run along the profile (edge,
  // upper side, back, lower side), kSteps per side, 3 kSteps per row.
  const Index back = static_cast<Index>(3 * kSteps * (kSteps / 2) + kSteps + kSteps / 2);
  ASSERT_DOUBLE_EQ(folded.vertices[back].x, 1.0);
  folded.vertices[back].y += 2.5 / kSteps;
  const std::size_t input_crossing = crossing_triangles(folded);
  ASSERT_GT(input_crossing, 0u);
  RemeshSettings s;
  s.vertices = 500;
  const RemeshResult r = remesh(folded, s);
  expect_topology_kept(r, folded);
  EXPECT_EQ(r.input_crossing_triangles, input_crossing);
  EXPECT_EQ(r.output_crossing_triangles, 0u);
}

TEST(HardCases, TwoSpheresNearlyTouching) {
  expect_valid_remesh(concatenate(icosphere(3), transformed(icosphere(3), 1.0, {2.01, 0, 0})), 600);
}

TEST(HardCases, ATinyComponentBesideALargeOne) {
  // Three triangles of a fan, far smaller than one output triangle, next to a sphere.
  TriangleMesh fan;
  fan.vertices = {{1.1, 0, 0}, {1.1, 0.01, 0}, {1.1, 0.005, 0.01}, {1.1, -0.005, 0.01}};
  fan.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}};
  expect_valid_remesh(concatenate(icosphere(3), fan), 500);
}

// 40 holes, each about a third of an output edge across: every one stays one boundary loop.
TEST(HardCases, ASphereWithManyHolesOfOneTriangle) {
  const TriangleMesh m = with_one_triangle_holes(icosphere(4), 40, 97);
  ASSERT_EQ(analyze_topology(m).boundary_loops, 40u);
  expect_valid_remesh(m, 500);
}

// A plate of 40 × 4 cells, each 10 times longer than wide, with 16 holes of one such sliver
// triangle each: the sizes graded down to their widths put more seeds on their loops than 100
// vertices leave, which was an error ("the sharp features need 105 vertices on their own, and
// the output has 100"); the count grows instead, to twice what they need (110 more), and the
// report says by how much.
TEST(HardCases, HolesThatNeedMoreSeedsThanTheCountGetMoreVertices) {
  const TriangleMesh plate = mapped_grid(40, 4, [](double u, double v) { return Vec3{u, v, 0}; });
  const TriangleMesh m = with_one_triangle_holes(plate, 16, 7);
  ASSERT_EQ(analyze_topology(m).boundary_loops, 17u);
  RemeshSettings s;
  s.vertices = 100;
  const RemeshResult r = remesh(m, s);
  expect_topology_kept(r, m);
  EXPECT_GT(r.count_grown, 0u);
  EXPECT_GE(r.mesh.vertices.size(), 100 + r.count_grown);
}

// A boundary that touches itself at a point, stored as two vertices there (beetle-alt.obj of a
// public test set, outside the corpus, crashed at 1k: feature seeds were placed once per point,
// so the corners after the pinch's second copy named other corners' seeds, and one past the end).
TEST(HardCases, ABoundaryThatTouchesItselfAtAPoint) {
  expect_valid_remesh(sheet_pinched_at_a_point(4), 300);
}

TEST(FeatureSeeds, CornersAtOnePointShareOneSeedThatEachNames) {
  const TriangleMesh sheet = sheet_pinched_at_a_point(4);
  Features features;  // the two copies of the pinch, and the sheet's first vertex: corners alone
  features.corners.push_back(0);
  for (Index v = 1; v < sheet.vertices.size(); ++v)
    if (std::count(sheet.vertices.begin(), sheet.vertices.end(), sheet.vertices[v]) == 2)
      features.corners.push_back(v);
  ASSERT_EQ(features.corners.size(), 3u);
  std::vector<Vec3> seeds = sample_surface(sheet, 40, 1);
  const SeedConstraints c = place_feature_seeds(seeds, sheet, features,
                                                CurveProjector(sheet, features), CurveSpacing(0.1));
  ASSERT_EQ(c.corner_seed.size(), features.corners.size());
  for (std::size_t k = 0; k < features.corners.size(); ++k) {
    EXPECT_EQ(seeds[c.corner_seed[k]], sheet.vertices[features.corners[k]]);
    EXPECT_EQ(c.kind[c.corner_seed[k]], SeedConstraints::Kind::corner);
  }
  EXPECT_EQ(c.corner_seed[1], c.corner_seed[2]);
  EXPECT_EQ(std::count(c.kind.begin(), c.kind.end(), SeedConstraints::Kind::corner), 2);
}

// Where two sheets touch at a point, the extraction needs a vertex of each there, and the two
// must share no neighbour (cow.obj of a public test set, outside the corpus, came out with one
// shared at 1k, 2k and 5k, which the weld made non-manifold).
TEST(PinchDefects, EachSheetNeedsAVertexAtThePointAndNoTwoShareANeighbour) {
  TriangleMesh surface;  // two corners at the origin, as remesh splits a pinch
  surface.vertices = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  const std::vector<Index> corners = {0, 1};
  TriangleMesh out;
  out.vertices = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 1, 0}};
  out.triangles = {{0, 2, 3}, {1, 4, 5}, {2, 6, 3}};
  EXPECT_TRUE(pinch_defects(surface, corners, out).empty());
  // A neighbour of both: the triangles at its edges to them.
  out.triangles = {{0, 2, 3}, {1, 4, 2}, {2, 6, 3}};
  EXPECT_EQ(pinch_defects(surface, corners, out), (std::vector<Triangle>{{0, 2, 3}, {1, 4, 2}}));
  // One vertex there (the other's triangles gone): the triangles near the point.
  out.triangles = {{0, 2, 3}, {2, 6, 3}, {4, 5, 3}};
  EXPECT_EQ(pinch_defects(surface, corners, out),
            (std::vector<Triangle>{{0, 2, 3}, {2, 6, 3}, {4, 5, 3}}));
  for (Vec3& v : out.vertices) v = v + Vec3{5, 0, 0};  // out of their reach, but for the one there
  out.vertices[0] = {0, 0, 0};
  EXPECT_EQ(pinch_defects(surface, corners, out), (std::vector<Triangle>{{0, 2, 3}}));
  out.vertices[0] = {5, 0, 0};
  // Corners at different points are no pinch.
  surface.vertices[1] = {0, 0, 1};
  EXPECT_TRUE(pinch_defects(surface, corners, out).empty());
}

// The cells around the hole are annuli in one piece, and the triangulation closes the hole
// without a defect to show where (a manifold sphere, χ 2 against 0): the per-piece Euler
// characteristic finds them (PieceEulerCollector).
TEST(HardCases, ATorusWhoseHoleIsSmallerThanTheEdgeLength) {
  // Major radius 1, tube radius 0.95: the hole is 0.1 across, the edge length about 0.25.
  expect_valid_remesh(torus(1.0, 0.95, 96, 48), 600);
}

TEST(HardCases, ATinyHoleWithTwoCornersStaysAHole) {
  // A flat diamond with a narrow rhombic hole 0.02 long at its centre, edge length about 0.1.
  // The hole's ends turn by 169 degrees and are corners; its sides turn by 11 and are not, so
  // its loop is two curves between the same two corners, too short for a seed of their own.
  constexpr double h = 0.01;
  TriangleMesh m;
  m.vertices = {{-1, 0, 0}, {0, -1, 0},      {1, 0, 0}, {0, 1, 0},
                {-h, 0, 0}, {0, -h / 10, 0}, {h, 0, 0}, {0, h / 10, 0}};
  for (Index i = 0; i < 4; ++i) {
    const Index next = (i + 1) % 4;
    m.triangles.push_back({i, next, 4 + next});
    m.triangles.push_back({i, 4 + next, 4 + i});
  }
  expect_valid_remesh(m, 300);
}

// The unit square as an n×n grid of quads, each split in two, without the quads of a centred
// window `window` wide and without one triangle of the quad row just past the window's top side:
// a hole of 3 vertices 1/n across, 1/n from the window's. One component, 3 boundary loops.
TriangleMesh sheet_with_window_and_pinhole(int n, double window) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.push_back({double(i) / n, double(j) / n, 0});
  const auto at = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  const int low = static_cast<int>(n * (0.5 - window / 2)),
            high = static_cast<int>(n * (0.5 + window / 2));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (low <= i && i < high && low <= j && j < high) continue;
      if (!(j == high + 1 && i == (low + high) / 2))
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  // The window's inner grid vertices go: the remesher takes only vertices that triangles use.
  std::vector<Index> id(m.vertices.size(), kNoIndex);
  TriangleMesh used;
  for (Triangle& t : m.triangles)
    for (Index& v : t) {
      if (id[v] == kNoIndex)
        id[v] = static_cast<Index>(used.vertices.size()), used.vertices.push_back(m.vertices[v]);
      v = id[v];
    }
  used.triangles = std::move(m.triangles);
  return used;
}

// An input with a face listed the other way round from the rest (multibody.stl of trimesh's test
// models, a box so: 2 components out of 1 at every count) is remeshed as if oriented.
TEST(HardCases, ABoxWithOneFaceListedTheOtherWayRound) {
  TriangleMesh box = cube(2);
  for (Triangle& t : box.triangles)
    if (std::all_of(t.begin(), t.end(), [&](Index v) { return box.vertices[v].z == 1; }))
      std::swap(t[1], t[2]);
  ASSERT_FALSE(analyze_topology(box).consistently_oriented);
  RemeshSettings s;
  s.vertices = 500;
  s.hausdorff.reset();
  const RemeshResult r = remesh(box, s);
  expect_topology_kept(r, box);
  EXPECT_TRUE(analyze_topology(r.mesh).consistently_oriented);
  EXPECT_GE(measure_quality(r.mesh).angle_min_deg, 30);
}

// A remesh to `vertices` with random seed `seed`, the defaults otherwise, without the report's
// Hausdorff distance.
RemeshResult remesh_with_seed(const TriangleMesh& input, std::size_t vertices, std::uint64_t seed) {
  RemeshSettings s;
  s.vertices = vertices;
  s.seed = seed;
  s.hausdorff.reset();
  return remesh(input, s);
}

// Validity first (issue 18): where even edge lengths cannot keep a hole apart from its
// neighbour (tower_holes.obj of a public test set, outside the corpus, lost one of its 38 loops
// at 1k this way), the remesh is redone with adaptive sizes, which give the narrow bridge cells
// its width, and the report says so. By default the even sizes grade down to the pinhole
// (SizingSettings::gap_gradation) and keep it from the start.
TEST(HardCases, AHoleBesideAnotherFarCloserThanTheEdgeLengthStaysApart) {
  const TriangleMesh sheet = sheet_with_window_and_pinhole(100, 0.3);
  ASSERT_EQ(analyze_topology(sheet).boundary_loops, 3u);
  int adapted = 0;
  for (const std::uint64_t seed : {1, 2, 3}) {
    // About 0.1 apart: the pinhole and its bridge to the window are a tenth of that.
    RemeshSettings s;
    s.vertices = 140;
    s.seed = seed;
    s.hausdorff.reset();
    const RemeshResult graded = remesh(sheet, s);
    expect_topology_kept(graded, sheet);
    EXPECT_FALSE(graded.sizes_adapted);
    EXPECT_GT(graded.gap_length_min, 0);
    EXPECT_LT(graded.gap_length_min, 0.2);
    s.sizing.gap_gradation = 0;
    const RemeshResult even = remesh(sheet, s);
    expect_topology_kept(even, sheet);
    EXPECT_EQ(even.gap_length_min, 0);
    adapted += even.sizes_adapted;
  }
  EXPECT_GT(adapted, 0);  // the even sizes lost the pinhole at least once
}

// A torus squashed to a twentieth of its height, a ring-shaped plate 0.03 thick, its two faces
// closer than the spacing at these counts (the kind of bench/fuzz.py round 6): the output keeps
// the genus and passes through itself nowhere, with even sizes and adaptive ones.
TEST(HardCases, ASquashedTorusIsAPlateWhoseOutputStaysEmbedded) {
  TriangleMesh plate = torus(1.0, 0.3, 120, 40);
  for (Vec3& p : plate.vertices) p.z *= 0.05;
  ASSERT_EQ(crossing_triangles(plate), 0u);
  for (const double adaptive : {0.0, 1.5})
    for (const std::size_t count : {200u, 500u}) {
      RemeshSettings s;
      s.vertices = count;
      s.sizing.adaptive = adaptive;
      s.hausdorff.reset();
      const RemeshResult r = remesh(plate, s);
      expect_topology_kept(r, plate);
      EXPECT_EQ(crossing_triangles(r.mesh), 0u) << count << (adaptive > 0 ? " adaptive" : "");
      EXPECT_EQ(r.output_crossing_triangles, 0u);
    }
}

// A torus whose tube, 2π · 0.03 ≈ 0.19 around, is about the spacing of 60 vertices (0.14): no
// round of topology control nor adaptive sizes keep its genus at 60, the count grows (issue 18
// item 2), and the report says by how much.
TEST(HardCases, ATubeTooThinForTheCountAskedForGetsMoreVertices) {
  const TriangleMesh ring = torus(1.0, 0.03, 400, 12);
  for (const std::uint64_t seed : {1, 2}) {
    const RemeshResult r = remesh_with_seed(ring, 60, seed);
    expect_topology_kept(r, ring);
    EXPECT_GT(r.count_grown, 0u);
    EXPECT_LE(r.count_grown, 3 * 60u);  // at most 4 times the count
    EXPECT_GE(r.mesh.vertices.size(), 60 + r.count_grown);
  }
}

// A torus whose tube is a third as thick again (0.01), at 20 vertices: its genus takes several
// hundred, past four times the count; under kSmallCount (remesh/topology_first) the count goes on
// doubling, as a small remesh costs little (femur.off at 50 kept its two thin handles at 400).
TEST(HardCases, ATubeFarTooThinForASmallCountGetsAsManyVerticesAsItNeeds) {
  const TriangleMesh ring = torus(1.0, 0.01, 1000, 12);
  const RemeshResult r = remesh_with_seed(ring, 20, 1);
  expect_topology_kept(r, ring);
  EXPECT_GT(r.count_grown, 3 * 20u);  // more than 4 times the count
  EXPECT_GE(r.mesh.vertices.size(), 20 + r.count_grown);
}

// A torus whose tube narrows from radius 0.3 to 0.003 (nu steps round, nv about): thick on one
// side, a hundred times thinner on the other.
TriangleMesh tapered_torus(int nu, int nv) {
  TriangleMesh m;
  const double tau = 2 * std::numbers::pi;
  for (int i = 0; i < nu; ++i) {
    const double u = tau * i / nu;
    const double r = 0.003 + (0.3 - 0.003) * (0.5 + 0.5 * std::cos(u));
    for (int j = 0; j < nv; ++j) {
      const double v = tau * j / nv;
      m.vertices.push_back({(1 + r * std::cos(v)) * std::cos(u),
                            (1 + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  }
  auto id = [&](int i, int j) { return static_cast<Index>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Where even sizes lose the topology at a grown count, adaptive ones are tried at that count
// too: the tapered torus at 60 vertices keeps its genus only so, at 240 (before, the even outputs
// at 60, 120 and 240 all cut its thin side, and the one at 60 was returned). From 791a1e8, where
// the adaptive sizes narrowed to its thin side's throat with π edges round it, as to a handle, it
// kept it at 120; with six edges round the throat, as round a hole, they take a third of the
// count there, and it kept it at 240 again; with the thin part's tighter cap (1.6 lfs, four edges
// round) where it takes little, at 120 once more. The progress callback hears of each round of
// topology control that adds seeds and of each redo.
TEST(HardCases, ATubeThatNarrowsFarBelowTheSpacingGetsAdaptiveSizesAtTheGrownCount) {
  const TriangleMesh ring = tapered_torus(600, 16);
  RemeshSettings s;
  s.vertices = 60;
  s.hausdorff.reset();
  std::vector<RemeshProgress> heard;
  s.progress = [&](const RemeshProgress& p) {
    if (p.phase == std::string("topology") || p.phase == std::string("redo")) heard.push_back(p);
  };
  const RemeshResult r = remesh(ring, s);
  expect_topology_kept(r, ring);
  EXPECT_TRUE(r.sizes_adapted);
  EXPECT_EQ(r.count_grown, 60u);  // at twice the count
  EXPECT_GE(r.mesh.vertices.size(), 60 + r.count_grown);
  // Redone with adaptive sizes at 60, then at 120 with even sizes, then adaptive.
  std::vector<std::pair<std::size_t, std::string>> redos;
  std::string last_redo;
  for (const RemeshProgress& p : heard)
    if (p.phase == std::string("redo")) {
      redos.push_back({p.seeds, p.detail});
      last_redo = progress_line(p);
    }
  const std::vector<std::pair<std::size_t, std::string>> expected{
      {60, "adaptive sizes"}, {120, "even sizes"}, {120, "adaptive sizes"}};
  EXPECT_EQ(redos, expected);
  ASSERT_FALSE(heard.empty());
  EXPECT_EQ(heard.front().phase, std::string("topology"));
  EXPECT_EQ(heard.front().iteration, 1);
  EXPECT_GT(heard.front().seeds, 60u);  // the first round's seeds came in
  EXPECT_NE(progress_line(heard.front()).find("topology"), std::string::npos);
  EXPECT_NE(last_redo.find("again at 120 vertices, adaptive sizes"), std::string::npos)
      << last_redo;
}

// Adaptive sizes grow with the count too: the same tube at 60, adaptive, kept its genus only once
// the count doubled (it stayed lost before, the growth being for even sizes alone).
TEST(HardCases, ATubeTooThinForTheCountGetsMoreVerticesWithAdaptiveSizesToo) {
  const TriangleMesh ring = torus(1.0, 0.03, 400, 12);
  RemeshSettings s;
  s.vertices = 60;
  s.sizing.adaptive = 1.5;
  s.hausdorff.reset();
  const RemeshResult r = remesh(ring, s);
  expect_topology_kept(r, ring);
  EXPECT_GT(r.count_grown, 0u);
  EXPECT_GE(r.mesh.vertices.size(), 60 + r.count_grown);
}

// Thinner still (0.003 around), the cells wrap around the tube at every count tried (to 1,280
// at 40), and meet in no triangle: an error that says so, not an empty output.
TEST(HardCases, ATubeFarTooThinForTheCountAskedForIsAnError) {
  RemeshSettings s;
  s.vertices = 40;
  s.hausdorff.reset();
  try {
    remesh(torus(1.0, 0.0005, 400, 12), s);
    FAIL() << "an output for cells that wrap around the tube";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("ask for more vertices"), std::string::npos) << e.what();
  }
}

// Where even sizes keep the topology, they stay, and with topology control off nothing is
// redone.
TEST(HardCases, EvenSizesThatKeepTheTopologyOrNoTopologyControlAreNotAdapted) {
  RemeshSettings s;
  s.vertices = 140;
  s.hausdorff.reset();
  EXPECT_FALSE(remesh(icosphere(3), s).sizes_adapted);
  s.topology_rounds = 0;
  EXPECT_FALSE(remesh(sheet_with_window_and_pinhole(100, 0.3), s).sizes_adapted);
}

// Three square sheets meeting along the line x = z = 0, a T in section: each n×n grid, vertices
// shared along the junction, whose n edges are used by three triangles each.
TriangleMesh three_sheet_junction(int n) {
  TriangleMesh m;
  std::map<Vec3, Index> id;
  auto vertex = [&](const Vec3& p) {
    const auto [it, added] = id.emplace(p, static_cast<Index>(m.vertices.size()));
    if (added) m.vertices.push_back(p);
    return it->second;
  };
  const std::function<Vec3(double, double)> sheets[] = {[](double u, double v) {
                                                          return Vec3{-1 + u, -1 + 2 * v, 0};
                                                        },
                                                        [](double u, double v) {
                                                          return Vec3{u, -1 + 2 * v, 0};
                                                        },
                                                        [](double u, double v) {
                                                          return Vec3{0, -1 + 2 * u, v};
                                                        }};
  for (const auto& at : sheets)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u0 = double(i) / n, u1 = double(i + 1) / n;
        const double v0 = double(j) / n, v1 = double(j + 1) / n;
        const Index a = vertex(at(u0, v0)), b = vertex(at(u1, v0)), c = vertex(at(u1, v1)),
                    d = vertex(at(u0, v1));
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      }
  return m;
}

// Issue 18: where the input is non-manifold, the output keeps those edges as features and adds
// no others, and topology control takes them for no defect. Before, its rounds refined around
// them, to no avail: 57 seeds added at 300 vertices, and triple_vierbein.obj took 12.9 s at 5k
// instead of 5.0 s (the same output).
TEST(NonManifoldInput, ASheetJunctionIsKeptWithoutRefiningAroundIt) {
  const TriangleMesh tee = three_sheet_junction(8);
  const TopologyReport in = analyze_topology(tee);
  ASSERT_EQ(in.nonmanifold_edges, 8u);
  RemeshSettings s;
  s.vertices = 300;
  const RemeshResult r = remesh(tee, s);
  const TopologyReport out = analyze_topology(r.mesh);
  EXPECT_TRUE(same_topology(out, in));
  EXPECT_EQ(out.nonmanifold_vertices, 0u);
  EXPECT_GT(out.nonmanifold_edges, 8u);  // the junction, at the output's spacing
  std::map<Edge, int> uses;
  for (const Triangle& t : r.mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  for (const auto& [e, count] : uses) {
    if (count < 3) continue;
    for (const Index v : e)  // on the junction line, exactly (curve seeds lie on its edges)
      EXPECT_TRUE(r.mesh.vertices[v].x == 0 && r.mesh.vertices[v].z == 0)
          << "a non-manifold edge off the junction at vertex " << v;
  }
  EXPECT_EQ(r.feature_edges_missing, 0u);
  EXPECT_EQ(r.islands_seeded + r.seeds_refined, 0u);
  EXPECT_EQ(r.mesh.vertices.size(), 300u);
  EXPECT_EQ(r.sheets_apart, 0u);  // kept whole: nothing to mend
}

TEST(HardCases, ANeedle) {
  // A cylinder of radius 0.01 and length 2, remeshed coarsely.
  TriangleMesh needle = cylinder(40, 12);
  for (Vec3& v : needle.vertices) v.x *= 0.01, v.y *= 0.01;
  expect_valid_remesh(needle, 200);
}

// A flat strip 3 long and 0.3 wide whose top side is a saw of `teeth` teeth, each one triangle
// as deep as it is wide: one boundary loop whose every vertex on the saw turns sharply.
TriangleMesh toothed_strip(int teeth) {
  TriangleMesh m;
  const double pitch = 3.0 / teeth;
  for (int i = 0; i <= teeth; ++i) {
    m.vertices.push_back({i * pitch, 0, 0});              // 3i: the saw's base
    m.vertices.push_back({i * pitch, -0.3, 0});           // 3i + 1: the strip's bottom side
    m.vertices.push_back({(i + 0.5) * pitch, pitch, 0});  // 3i + 2: a tip (the last unused)
  }
  for (Index i = 0; i < static_cast<Index>(teeth); ++i) {
    add_quad(m, 3 * i + 1, 3 * i + 4, 3 * i + 3, 3 * i);
    m.triangles.push_back({3 * i, 3 * i + 3, 3 * i + 2});
  }
  m.vertices.pop_back();
  return m;
}

TEST(HardCases, AStripWithHundredsOfBoundaryTeeth) {
  const TriangleMesh strip = toothed_strip(300);
  ASSERT_EQ(analyze_topology(strip).boundary_loops, 1u);
  // Teeth a fifth of the edge length wide: the saw's 599 sharp turns are no corners at that
  // scale (with them, 500 vertices were too few for the corners alone).
  expect_valid_remesh(strip, 500);
  // 0.7 of it: every turn is a corner, kept.
  RemeshSettings s;
  s.vertices = 5000;
  const RemeshResult r = remesh(strip, s);
  expect_topology_kept(r, strip);
  EXPECT_EQ(r.features.corners.size(), 601u);  // the saw's, and the strip's bottom two
  EXPECT_GE(measure_quality(r.mesh).angle_min_deg, 20.0);
}

TEST(HardCases, FewAndManyVertices) {
  const TriangleMesh t = torus(1.0, 0.3, 64, 24);
  expect_valid_remesh(t, 200);
  expect_valid_remesh(t, 20000);
}

// A slab thinner than the noise on it: its two faces pass through each other over much of their
// area, so that no count or sizing gives the output the input's topology. The rounds are not
// pinned and the remesh is not tried again (blade.off with noise of 5% of an edge, 28% of its
// triangles crossing, took over 300 s at 9k in rounds and retries that never kept it); the output
// is still a manifold, and the report counts the crossings.
TEST(HardCases, ASlabFoldedThroughItselfIsNotRetried) {
  TriangleMesh slab = cube(8);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> noise(-0.04, 0.04);
  for (Vec3& v : slab.vertices) v.z = 0.01 * v.z + noise(random);
  ASSERT_EQ(analyze_topology(slab).components, 1u);
  RemeshSettings s;
  s.vertices = 200;
  s.topology_rounds = 1;
  s.hausdorff.reset();
  std::vector<RemeshProgress> heard;
  s.progress = [&](const RemeshProgress& p) {
    if (p.phase == std::string("topology") || p.phase == std::string("redo")) heard.push_back(p);
  };
  const RemeshResult r = remesh(slab, s);
  EXPECT_TRUE(crosses_itself_widely(r.input_crossing_triangles, r.input_topology.triangles))
      << r.input_crossing_triangles << " of " << r.input_topology.triangles;
  for (const RemeshProgress& p : heard) {
    EXPECT_NE(p.phase, std::string("redo")) << progress_line(p);
    EXPECT_LE(p.iteration, s.topology_rounds) << progress_line(p);  // none pinned
  }
  const TopologyReport out = analyze_topology(r.mesh);
  EXPECT_TRUE(out.is_manifold());
  EXPECT_TRUE(out.is_closed());
  EXPECT_GT(measure_quality(r.mesh).angle_min_deg, 1e-3);  // no triangle of no area
}

TEST(HardCases, CrossingWidelyIsATwentiethOfTheTriangles) {
  EXPECT_FALSE(crosses_itself_widely(0, 100));
  EXPECT_FALSE(crosses_itself_widely(4, 100));
  EXPECT_TRUE(crosses_itself_widely(5, 100));
  EXPECT_TRUE(crosses_itself_widely(1, 1));
}

}  // namespace

}  // namespace cvtmesh
