// What a TraversalMemory holds (cvtmesh/rvd.hpp): the polygons of one RVD traversal, by
// triangle, with how far each triangle's polygons reach from their seeds. A triangle that no seed
// which moved, came or went can reach keeps its polygons in the next diagram: each of its points
// is nearer to its old seed than that reach, and only a changed seed could now be nearer still.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "cvtmesh/rvd.hpp"
#include "voronoi/seed_neighbors.hpp"

namespace cvtmesh {

class TraversalRecord {
 public:
  // Whether the record is of a traversal of `surface` (the same object, of the same size).
  bool covers(const TriangleMesh& surface) const;
  // Triangles per chunk of the traversal recorded.
  std::size_t chunk_size() const { return chunk_size_; }
  // Frees chunk `chunk`, which is not replayed again.
  void release(std::size_t chunk) { chunks_[chunk] = {}; }
  // Per triangle of the surface, whether its polygons may differ for the diagram of `seeds`:
  // one of its polygons, or a bisector of theirs, is of a seed that moved or went; or a seed
  // that moved or came is within the polygons' reach of the triangle.
  std::vector<char> stale_triangles(const std::vector<Vec3>& seeds) const;
  // Hands triangle t's polygons, as recorded, to each sink as part of chunk `chunk`; returns
  // how many there were. `buffer`: scratch for their vertices.
  std::size_t replay(std::size_t t, std::size_t chunk, std::span<PolygonSink* const> sinks,
                     std::vector<RvdVertex>& buffer) const;
  // How many polygons triangle t has.
  std::size_t polygon_count(std::size_t t) const {
    const Chunk& c = chunk_of(t);
    return c.first[t % chunk_size_ + 1] - c.first[t % chunk_size_];
  }

 private:
  friend class PolygonRecorder;
  // The polygons of a chunk of consecutive triangles, in traversal order. A polygon is kept as
  // the planes of its sides, in order (an input edge or a bisector: a vertex's symbol, see
  // RvdVertex); each vertex, on the planes of the sides before and after it, is made again from
  // them by predicates::vertex_with_symbols, bit for bit. A tenth of the space of the vertices:
  // with the record, igea.ply's remesh to 10k peaks at 204 MB (187 without); with the vertices
  // whole, it peaked at 220.
  struct Chunk {
    std::vector<std::uint32_t> first;  // per triangle, its first polygon; then the polygon count
    std::vector<Index> seed;           // per polygon
    // Per polygon, one past its last side in `planes`. A polygon with no sides there is the
    // whole triangle (its three corners), which a fine input has for most triangles.
    std::vector<std::uint32_t> end;
    std::vector<std::int32_t> planes;  // per side, from vertex k to k + 1
    // The vertices that their planes do not give (an ill-conditioned crossing, placed by
    // interpolation), whole, by the index in `planes` of the side that follows them, in order.
    std::vector<std::pair<std::uint32_t, RvdVertex>> placed;
    std::vector<double> reach2;  // per triangle: its polygons' squared reach, rounded up
  };
  const Chunk& chunk_of(std::size_t t) const { return chunks_[t / chunk_size_]; }

  const TriangleMesh* surface_ = nullptr;
  std::size_t triangle_count_ = 0, vertex_count_ = 0;
  std::vector<Vec3> seeds_;
  std::size_t chunk_size_ = 1;
  std::vector<Chunk> chunks_;
};

// Records the polygons it gets, chunk by chunk as the traversal runs, into a new record.
class PolygonRecorder : public PolygonSink {
 public:
  // `chunk_size`: triangles per chunk of the traversal.
  PolygonRecorder(const TriangleMesh& surface, const std::vector<Vec3>& seeds,
                  std::size_t chunk_size);
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  void end() override;
  // Takes chunk `chunk` of `old`, made with the same chunk size, as this traversal's: its
  // polygons are the same (they went to the other sinks only).
  void adopt(std::size_t chunk, TraversalRecord& old);
  // After the last polygon of chunk `chunk`: its arrays shrink to what they hold (grown by
  // doubling, they may hold twice that, and the record is kept from one extraction to the next).
  void finish(std::size_t chunk);
  TraversalRecord take() && { return std::move(record_); }

 private:
  // Chunk `chunk`, its per-triangle arrays made on first use (those taken over have theirs).
  TraversalRecord::Chunk& started(std::size_t chunk);

  TraversalRecord record_;
  std::vector<std::size_t> next_;  // per chunk, the first triangle whose `first` is not set yet
};

struct TraversalMemory::State {
  TraversalRecord record;
  // Of the record: a number no other record has had (0: none), which the sinks that keep chunks
  // hold when they served the traversal that made it (PolygonSink::keeps_chunks). A traversal
  // that changes no chunk keeps it.
  std::uint64_t version = 0;
  // The lists of the last diagram made with the memory (shared with it), and its seeds.
  std::shared_ptr<const SeedNeighbors> lists;
  std::vector<Vec3> lists_at;
};

}  // namespace cvtmesh
