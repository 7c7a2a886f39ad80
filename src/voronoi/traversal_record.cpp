#include "voronoi/traversal_record.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "predicates/side_of_bisector.hpp"
#include "voronoi/polygon_reach.hpp"

namespace cvtmesh {

namespace {

bool same(const RvdVertex& a, const RvdVertex& b) {
  return a.point == b.point && a.error == b.error && a.symbols == b.symbols;
}

// The vertex between sides on planes `before` and `after`, as the traversal makes it: its symbols
// in ascending order (bisector_crossing's), or an input corner.
RvdVertex vertex_between(const predicates::ClipFrame& frame, std::int32_t before,
                         std::int32_t after) {
  return predicates::vertex_with_symbols(frame, {std::min(before, after), std::max(before, after)});
}

}  // namespace

TraversalMemory::TraversalMemory() = default;
TraversalMemory::~TraversalMemory() = default;

bool TraversalRecord::covers(const TriangleMesh& surface) const {
  return surface_ == &surface && triangle_count_ == surface.triangles.size() &&
         vertex_count_ == surface.vertices.size();
}

std::vector<char> TraversalRecord::stale_triangles(const std::vector<Vec3>& seeds) const {
  const SeedChanges changes(seeds_, seeds);
  const auto changed_plane = [&](std::int32_t s) {
    return s >= 0 && changes.changed(static_cast<Index>(s));
  };
  std::vector<char> stale(triangle_count_, 0);
  tbb::parallel_for(std::size_t{0}, triangle_count_, [&](std::size_t t) {
    const Chunk& c = chunk_of(t);
    const std::size_t local = t % chunk_size_;
    for (std::uint32_t p = c.first[local]; p < c.first[local + 1]; ++p) {
      const std::uint32_t begin = p == 0 ? 0 : c.end[p - 1];
      if (changes.changed(c.seed[p]) ||
          std::any_of(c.planes.begin() + begin, c.planes.begin() + c.end[p], changed_plane)) {
        stale[t] = 1;
        return;
      }
    }
    // A point of the triangle nearer to an arrived seed than to its own is within the reach of
    // the triangle's polygons from that seed: the arrived seed is within the triangle's bounding
    // ball grown by that reach (margins far beyond rounding).
    const auto [a, b, q] = surface_->corners(t);
    const Vec3 centre = (1.0 / 3) * (a + b + q);
    const Vec3* nearest = changes.nearest_arrived(centre);
    if (!nearest) return;
    const double radius = std::max({distance(a, centre), distance(b, centre), distance(q, centre)});
    const double reach = std::sqrt(c.reach2[local]);
    stale[t] = distance(*nearest, centre) <= (radius + reach) * (1 + 1e-9) + 1e-300;
  });
  return stale;
}

std::size_t TraversalRecord::replay(std::size_t t, std::size_t chunk,
                                    std::span<PolygonSink* const> sinks,
                                    std::vector<RvdVertex>& buffer) const {
  const Chunk& c = chunk_of(t);
  const std::size_t local = t % chunk_size_;
  const std::array<Vec3, 3> corners = surface_->corners(t);
  for (std::uint32_t p = c.first[local]; p < c.first[local + 1]; ++p) {
    const predicates::ClipFrame frame{corners, seeds_.data(), c.seed[p]};
    const std::uint32_t begin = p == 0 ? 0 : c.end[p - 1];
    buffer.clear();
    if (begin == c.end[p]) {
      for (int k = 0; k < 3; ++k) buffer.push_back(predicates::corner_vertex(frame, k));
    } else {
      auto placed = std::lower_bound(c.placed.begin(), c.placed.end(), begin,
                                     [](const auto& e, std::uint32_t i) { return e.first < i; });
      for (std::uint32_t k = begin; k < c.end[p]; ++k) {
        if (placed != c.placed.end() && placed->first == k)
          buffer.push_back((placed++)->second);
        else
          buffer.push_back(
              vertex_between(frame, c.planes[k == begin ? c.end[p] - 1 : k - 1], c.planes[k]));
      }
    }
    const RvdPolygon polygon{c.seed[p], static_cast<Index>(t), buffer};
    for (PolygonSink* sink : sinks) sink->polygon(chunk, polygon);
  }
  return c.first[local + 1] - c.first[local];
}

PolygonRecorder::PolygonRecorder(const TriangleMesh& surface, const std::vector<Vec3>& seeds,
                                 std::size_t chunk_size) {
  record_.surface_ = &surface;
  record_.triangle_count_ = surface.triangles.size();
  record_.vertex_count_ = surface.vertices.size();
  record_.seeds_ = seeds;
  record_.chunk_size_ = chunk_size;
}

void PolygonRecorder::begin(std::size_t chunks) {
  record_.chunks_.assign(chunks, {});
  next_.resize(chunks);
  for (std::size_t c = 0; c < chunks; ++c) next_[c] = c * record_.chunk_size_;
}

TraversalRecord::Chunk& PolygonRecorder::started(std::size_t chunk) {
  TraversalRecord::Chunk& c = record_.chunks_[chunk];
  if (c.first.empty()) {  // not yet written, nor taken over from the last record
    const std::size_t begin = chunk * record_.chunk_size_;
    const std::size_t end = std::min(record_.triangle_count_, begin + record_.chunk_size_);
    c.first.assign(end - begin + 1, 0);
    c.reach2.assign(end - begin, 0);
  }
  return c;
}

void PolygonRecorder::polygon(std::size_t chunk, const RvdPolygon& polygon) {
  TraversalRecord::Chunk& c = started(chunk);
  const std::size_t begin = chunk * record_.chunk_size_;
  const auto count = static_cast<std::uint32_t>(c.seed.size());
  for (; next_[chunk] <= polygon.triangle; ++next_[chunk]) c.first[next_[chunk] - begin] = count;
  const predicates::ClipFrame frame{record_.surface_->corners(polygon.triangle),
                                    record_.seeds_.data(), polygon.seed};
  const bool whole = polygon.vertices.size() == 3 &&
                     same(polygon.vertices[0], predicates::corner_vertex(frame, 0)) &&
                     same(polygon.vertices[1], predicates::corner_vertex(frame, 1)) &&
                     same(polygon.vertices[2], predicates::corner_vertex(frame, 2));
  if (!whole) {
    const std::span<const RvdVertex> v = polygon.vertices;
    const auto first = static_cast<std::uint32_t>(c.planes.size());
    for (std::size_t k = 0; k < v.size(); ++k)
      c.planes.push_back(predicates::common_symbol(v[k], v[(k + 1) % v.size()]));
    // A vertex that its planes would not give bit for bit is kept whole (see Chunk).
    for (std::size_t k = 0; k < v.size(); ++k) {
      const std::int32_t before = c.planes[first + (k == 0 ? v.size() - 1 : k - 1)];
      if (!same(v[k], vertex_between(frame, before, c.planes[first + k])))
        c.placed.emplace_back(first + static_cast<std::uint32_t>(k), v[k]);
    }
  }
  c.seed.push_back(polygon.seed);
  c.end.push_back(static_cast<std::uint32_t>(c.planes.size()));
  double& reach2 = c.reach2[polygon.triangle - begin];
  reach2 = std::max(reach2, squared_reach(record_.seeds_[polygon.seed], polygon.vertices));
}

void PolygonRecorder::adopt(std::size_t chunk, TraversalRecord& old) {
  record_.chunks_[chunk] = std::move(old.chunks_[chunk]);
  next_[chunk] = std::min(record_.triangle_count_, (chunk + 1) * record_.chunk_size_);
}

void PolygonRecorder::finish(std::size_t chunk) {
  TraversalRecord::Chunk& c = record_.chunks_[chunk];
  c.seed.shrink_to_fit();
  c.end.shrink_to_fit();
  c.planes.shrink_to_fit();
  c.placed.shrink_to_fit();
}

void PolygonRecorder::end() {
  for (std::size_t chunk = 0; chunk < record_.chunks_.size(); ++chunk) {
    TraversalRecord::Chunk& c = started(chunk);
    const std::size_t begin = chunk * record_.chunk_size_;
    const auto count = static_cast<std::uint32_t>(c.seed.size());
    for (std::size_t t = next_[chunk] - begin; t < c.first.size(); ++t) c.first[t] = count;
  }
}

}  // namespace cvtmesh
