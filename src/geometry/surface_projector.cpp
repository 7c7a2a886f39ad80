#include "geometry/surface_projector.hpp"

#include <CGAL/AABB_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>
#include <nanoflann.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/index_range.hpp"
#include "geometry/kd_nearest.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

namespace {
// Plain doubles: a nearest point is a construction, rounded whatever the kernel, and the filtered
// box-sphere tests of an exact-predicates kernel only decide which boxes the search opens, a
// rounding's difference at most (spool.off at 5k: the whole remesh 8% faster).
using Kernel = CGAL::Simple_cartesian<double>;

Vec3 vec(const Kernel::Point_3& p) {
  return {p.x(), p.y(), p.z()};
}

Kernel::Point_3 point(const Vec3& p) {
  return {p.x, p.y, p.z};
}

// The projector's triangles as corner ids into a copy of the surface's points: a third of the
// memory of CGAL triangles (igea.ply: 6 MB against 19 MB), the tree's primitives being ids alone.
struct TriangleStore {
  std::vector<Vec3> points;
  std::vector<Triangle> corners;

  Vec3 corner(std::uint32_t triangle, int k) const { return points[corners[triangle][k]]; }
  // Coordinate k of the triangle's centroid (as CGAL::centroid makes it, bit for bit).
  double centroid(std::uint32_t triangle, int k) const {
    const Triangle& c = corners[triangle];
    return (points[c[0]][k] + points[c[1]][k] + points[c[2]][k]) / 3;
  }
  Vec3 centroid(std::uint32_t triangle) const {
    return {centroid(triangle, 0), centroid(triangle, 1), centroid(triangle, 2)};
  }
};

// nanoflann's view of the triangles' centroids: where a query has no hint, it starts from the
// nearest centroid. An array of them is kept only while the tree is built, which reads each
// many times; queries, which read a few, make them as they go (the array took 24 bytes a
// triangle: 48 MB on a 2M-triangle input).
struct Centroids {
  const TriangleStore* store;
  const std::vector<Vec3>* while_building = nullptr;
  std::size_t kdtree_get_point_count() const { return store->corners.size(); }
  double kdtree_get_pt(std::size_t t, std::size_t dim) const {
    const auto k = static_cast<int>(dim);
    return while_building ? (*while_building)[t][k]
                          : store->centroid(static_cast<std::uint32_t>(t), k);
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using CentroidTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Centroids>, Centroids,
                                        3, Index>;

// What CGAL's tree reads of a primitive, from its id: its triangle, and its reference point (its
// first corner, as CGAL's own triangle primitive has it).
Kernel::Triangle_3 triangle_of(const TriangleStore& store, std::uint32_t t) {
  return {point(store.corner(t, 0)), point(store.corner(t, 1)), point(store.corner(t, 2))};
}

Kernel::Point_3 first_corner_of(const TriangleStore& store, std::uint32_t t) {
  return point(store.corner(t, 0));
}

// A readable property map from a triangle's id to what `make` builds of it.
template <class Value, Value (*make)(const TriangleStore&, std::uint32_t)>
struct StoreMap {
  using key_type = std::uint32_t;
  using value_type = Value;
  using reference = Value;
  using category = boost::readable_property_map_tag;
  const TriangleStore* store = nullptr;

  friend Value get(const StoreMap& m, key_type t) { return make(*m.store, t); }
};

using TriangleOf = StoreMap<Kernel::Triangle_3, &triangle_of>;
using FirstCornerOf = StoreMap<Kernel::Point_3, &first_corner_of>;

using Primitive =
    CGAL::AABB_primitive<std::uint32_t, TriangleOf, FirstCornerOf, CGAL::Tag_true, CGAL::Tag_false>;
using AabbTraits = CGAL::AABB_traits<Kernel, Primitive>;
using AabbTree = CGAL::AABB_tree<AabbTraits>;

// The point of triangle abc nearest to p, by the region of the triangle's plane that p projects
// into (vertex, edge or face; Ericson, Real-Time Collision Detection §5.1.5). abc must have an
// area.
Vec3 nearest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = 1 / (va + vb + vc);
  return a + (vb * denominator) * ab + (vc * denominator) * ac;
}

// The point of triangle t (unit normal n, zero if it has no area) nearest to q.
Vec3 nearest_on(const Vec3& q, const TriangleStore& store, std::uint32_t t, const Vec3& n) {
  const Vec3 a = store.corner(t, 0), b = store.corner(t, 1), c = store.corner(t, 2);
  return n != Vec3{} ? nearest_on_triangle(q, a, b, c)
                     : vec(Kernel().construct_projected_point_3_object()(
                           Kernel::Triangle_3(point(a), point(b), point(c)), point(q)));
}

// The squared distance from q to triangle t (unit normal n, zero if it has no area), as the
// searches measure it.
double squared_distance_to_triangle(const Vec3& q, const TriangleStore& store, std::uint32_t t,
                                    const Vec3& n) {
  const Vec3 foot = nearest_on(q, store, t, n);
  return dot(q - foot, q - foot);
}

// The squared distance from q to a box.
double squared_distance_to_box(const Vec3& q, const CGAL::Bbox_3& box) {
  double squared = 0;
  for (int k = 0; k < 3; ++k) {
    const double x = q[k], gap = std::max({box.min(k) - x, 0.0, x - box.max(k)});
    squared += gap * gap;
  }
  return squared;
}

// A nearest-point search of the AABB tree (CGAL's traversal, our traits): CGAL's own traits
// project the query onto every triangle whose box the search opens, with the kernel's general
// construction. Here a triangle whose plane already lies farther than the nearest point found so
// far is skipped, and the rest are projected by nearest_on_triangle: on the shared meshes' CCVT
// the projections were a quarter of a remesh (anchor.off at 5k), most of them onto triangles
// that a plane test rules out.
class NearestTraits {
 public:
  // The search starts from the hint's triangle: its nearest point to the query, where the query
  // has moved from the hint's point, bounds the search far tighter than the hint's point does (a
  // seed that moved along the surface between two CVT steps is still about on its triangle).
  NearestTraits(const Vec3& query, const Vec3& hint, std::uint32_t hint_triangle,
                const TriangleStore& store, const std::vector<Vec3>& normals)
      : query_(query),
        nearest_(hint),
        triangle_(hint_triangle),
        squared_(squared_distance(query, hint)),
        store_(store),
        normals_(normals) {
    try_triangle(hint_triangle);
  }

  static constexpr bool go_further() { return true; }

  void intersection(const Kernel::Point_3&, const Primitive& primitive) {
    try_triangle(primitive.id());
  }

  bool do_intersect(const Kernel::Point_3&, const CGAL::AABB_node<AabbTraits>& node) const {
    return squared_distance_to_box(query_, node.bbox()) < squared_;
  }

  Vec3 nearest() const { return nearest_; }
  std::uint32_t triangle() const { return triangle_; }

 private:
  static double squared_distance(const Vec3& a, const Vec3& b) { return dot(a - b, a - b); }

  // Takes triangle `id`'s nearest point if it is nearer than the nearest so far.
  void try_triangle(std::uint32_t id) {
    const Vec3& n = normals_[id];
    const double height = dot(query_ - store_.corner(id, 0), n);
    if (n != Vec3{} && height * height >= squared_) return;
    const Vec3 p = nearest_on(query_, store_, id, n);
    const double squared = squared_distance(query_, p);
    if (squared < squared_) {
      squared_ = squared;
      nearest_ = p;
      triangle_ = id;
    }
  }

  Vec3 query_, nearest_;
  std::uint32_t triangle_;
  double squared_;
  const TriangleStore& store_;
  const std::vector<Vec3>& normals_;
};
// A search of the AABB tree for any triangle within a reach of the query: it opens only the
// boxes within reach, and stops at the first such triangle. Distances as NearestTraits measures
// them, so that a triangle found within reach holds the nearest point within reach too.
class WithinTraits {
 public:
  WithinTraits(const Vec3& query, double squared_reach, const TriangleStore& store,
               const std::vector<Vec3>& normals)
      : query_(query), squared_reach_(squared_reach), store_(store), normals_(normals) {}

  bool go_further() const { return !found_; }

  void intersection(const Kernel::Point_3&, const Primitive& primitive) {
    if (found_) return;
    const std::uint32_t t = primitive.id();
    const Vec3& n = normals_[t];
    const double height = dot(query_ - store_.corner(t, 0), n);
    if (height * height > squared_reach_) return;  // its plane is out of reach
    const double squared = squared_distance_to_triangle(query_, store_, t, n);
    if (squared > squared_reach_) return;
    found_ = SurfaceProjector::Near{squared, t};
  }

  bool do_intersect(const Kernel::Point_3&, const CGAL::AABB_node<AabbTraits>& node) const {
    return squared_distance_to_box(query_, node.bbox()) <= squared_reach_;
  }

  const std::optional<SurfaceProjector::Near>& found() const { return found_; }

 private:
  Vec3 query_;
  double squared_reach_;
  const TriangleStore& store_;
  const std::vector<Vec3>& normals_;
  std::optional<SurfaceProjector::Near> found_;
};

// The crossing of segment [a, b] with the surface nearest its midpoint (CGAL's traversal, our
// traits): each crossing, as its parameter s in [0, 1] along the segment and its triangle, goes
// to `found`, which says whether it takes it; one taken narrows the search to the part of the
// segment nearer the midpoint, so that fewer boxes open after it (the crossing nearest the
// midpoint is found all the same, and the first found of two as near, as without). CGAL's own
// segment queries construct each crossing with the kernel's general intersection of a segment and
// a triangle, and were most of the fit's time (finish/fit_surface asks for every vertex, edge
// midpoint and centroid, every round); here a slab test opens a box, and the crossing is Möller
// and Trumbore's (barycentric coordinates and the parameter from one cross product each),
// accepted a hair (1e-12) past the triangle's edges and the segment's ends, so that a segment
// through an edge or a vertex is seen by a triangle there. A segment in a triangle's plane meets
// it at no single point: no crossing there.
template <class Found>
class SegmentTraits {
 public:
  SegmentTraits(const Vec3& a, const Vec3& b, const TriangleStore& store, const Found& found)
      : a_(a), d_(b - a), store_(store), found_(found) {
    for (int k = 0; k < 3; ++k) inverse_[k] = d_[k] != 0 ? 1 / d_[k] : 0;
  }

  static constexpr bool go_further() { return true; }

  void intersection(const Kernel::Point_3&, const Primitive& primitive) {
    const std::uint32_t t = primitive.id();
    const Vec3 q0 = store_.corner(t, 0), e1 = store_.corner(t, 1) - q0,
               e2 = store_.corner(t, 2) - q0;
    const Vec3 h = cross(d_, e2);
    const double det = dot(e1, h);
    if (det == 0 || !std::isfinite(det)) return;
    const double inverse = 1 / det;
    const Vec3 w = a_ - q0;
    const double u = dot(w, h) * inverse;
    if (u < -kSlack || u > 1 + kSlack) return;
    const Vec3 g = cross(w, e1);
    const double v = dot(d_, g) * inverse;
    if (v < -kSlack || u + v > 1 + kSlack) return;
    const double s = dot(e2, g) * inverse;
    if (s < low_ || s > high_) return;
    const double at = std::clamp(s, 0.0, 1.0);
    if (!found_(at, t)) return;
    const double half = std::abs(at - 0.5);
    low_ = 0.5 - half - kSlack;
    high_ = 0.5 + half + kSlack;
  }

  // The slab test: whether the segment's parameters within the box's three slabs overlap, with
  // the same slack, on the part of the segment still searched.
  bool do_intersect(const Kernel::Point_3&, const CGAL::AABB_node<AabbTraits>& node) const {
    const CGAL::Bbox_3& box = node.bbox();
    double low = low_, high = high_;
    for (int k = 0; k < 3; ++k) {
      const double from = a_[k];
      if (d_[k] == 0) {
        if (from < box.min(k) || from > box.max(k)) return false;
        continue;
      }
      double s0 = (box.min(k) - from) * inverse_[k], s1 = (box.max(k) - from) * inverse_[k];
      if (s0 > s1) std::swap(s0, s1);
      low = std::max(low, s0 - kSlack);
      high = std::min(high, s1 + kSlack);
      if (low > high) return false;
    }
    return true;
  }

 private:
  static constexpr double kSlack = 1e-12;
  Vec3 a_, d_;
  std::array<double, 3> inverse_{};
  double low_ = -kSlack, high_ = 1 + kSlack;  // the part of the segment searched
  const TriangleStore& store_;
  const Found& found_;
};

}  // namespace

struct SurfaceProjector::Tree {
  TriangleStore store;
  std::vector<Vec3> normals;
  std::vector<Index> surface_id;      // per triangle, its id in the surface
  std::size_t surface_triangles = 0;  // in the surface given
  AabbTree tree;
  Centroids centroids{&store};  // the start of a query with no hint
  std::optional<CentroidTree> nearest_centroid;

  Foot foot(const Vec3& point, std::uint32_t triangle) const {
    return {point, normals[triangle], triangle};
  }
};

SurfaceProjector::SurfaceProjector(const TriangleMesh& surface) : tree_(std::make_unique<Tree>()) {
  require_index_range(surface.triangles.size(), "triangles for the surface projector");
  TriangleStore& store = tree_->store;
  store.points = surface.vertices;
  tree_->surface_triangles = surface.triangles.size();
  // Degenerate triangles hold no nearest point that a neighbour does not hold too; they are
  // kept only when nothing else is left, with a zero normal.
  for (const bool keep_degenerate : {false, true}) {
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
      const auto [a, b, c] = surface.corners(t);
      const Vec3 n = cross(b - a, c - a);
      if (norm(n) == 0 && !keep_degenerate) continue;
      store.corners.push_back(surface.triangles[t]);
      tree_->normals.push_back(unit_or_zero(n));
      tree_->surface_id.push_back(static_cast<Index>(t));
    }
    if (!store.corners.empty()) break;
  }
  store.corners.shrink_to_fit();
  tree_->normals.shrink_to_fit();
  tree_->surface_id.shrink_to_fit();
  const auto count = static_cast<std::uint32_t>(store.corners.size());
  tree_->tree.insert(boost::counting_iterator<std::uint32_t>(0),
                     boost::counting_iterator<std::uint32_t>(count), TriangleOf{&store},
                     FirstCornerOf{&store});
  tree_->tree.build();
  // A query without a hint starts from the nearest triangle centroid: a kd-tree over them is
  // faster to build than CGAL's own (accelerate_distance_queries), as fast to query.
  tree_->tree.do_not_accelerate_distance_queries();
  std::vector<Vec3> centroids(count);
  for (std::uint32_t t = 0; t < count; ++t) centroids[t] = store.centroid(t);
  tree_->centroids.while_building = &centroids;
  tree_->nearest_centroid.emplace(3, tree_->centroids,
                                  nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree_->nearest_centroid->buildIndex();
  tree_->centroids.while_building = nullptr;
}

SurfaceProjector::~SurfaceProjector() = default;

SurfaceProjector::Foot SurfaceProjector::nearest(const Vec3& p) const {
  const Index t = nearest_id(*tree_->nearest_centroid, p);
  return nearest(p, {tree_->store.centroid(t), tree_->normals[t], t});
}

SurfaceProjector::Foot SurfaceProjector::nearest(const Vec3& p, const Foot& hint) const {
  NearestTraits search(p, hint.point, static_cast<std::uint32_t>(hint.triangle), tree_->store,
                       tree_->normals);
  tree_->tree.traversal(point(p), search);
  return tree_->foot(search.nearest(), search.triangle());
}

std::optional<SurfaceProjector::Near> SurfaceProjector::within(const Vec3& p, double squared_reach,
                                                               std::size_t hint) const {
  if (const double squared = squared_distance_to(p, hint); squared <= squared_reach)
    return Near{squared, hint};
  return within(p, squared_reach);
}

std::optional<SurfaceProjector::Near> SurfaceProjector::within(const Vec3& p,
                                                               double squared_reach) const {
  WithinTraits search(p, squared_reach, tree_->store, tree_->normals);
  tree_->tree.traversal(point(p), search);
  return search.found();
}

std::optional<double> SurfaceProjector::along(const Vec3& p, const Vec3& direction, double reach,
                                              const Vec3& facing) const {
  // No line (a zero direction), or nothing to search (an unused vertex's infinite reach).
  if (!(reach > 0) || !std::isfinite(reach) || direction == Vec3{}) return std::nullopt;
  const Vec3 a = p - reach * direction, b = p + reach * direction;
  std::optional<double> nearest;
  // Each crossing as the tree finds it, in its order (nothing stored): taken where it is nearer.
  const auto found = [&](double s, std::uint32_t triangle) {
    if (facing != Vec3{} && !(dot(tree_->normals[triangle], facing) > 0)) return false;
    const double t = dot((a + s * (b - a)) - p, direction);
    if (nearest && !(std::abs(t) < std::abs(*nearest))) return false;
    nearest = t;
    return true;
  };
  SegmentTraits search(a, b, tree_->store, found);
  tree_->tree.traversal(point(p), search);
  return nearest;
}

std::size_t SurfaceProjector::surface_triangle(std::size_t triangle) const {
  return tree_->surface_id[triangle];
}

std::span<const Vec3> SurfaceProjector::unit_normals() const {
  // Triangles are left out in one case only: some had no area and others had.
  if (tree_->normals.size() != tree_->surface_triangles) return {};
  return tree_->normals;
}

double SurfaceProjector::squared_distance_to(const Vec3& p, std::size_t triangle) const {
  return squared_distance_to_triangle(p, tree_->store, static_cast<std::uint32_t>(triangle),
                                      tree_->normals[triangle]);
}

}  // namespace cvtmesh
