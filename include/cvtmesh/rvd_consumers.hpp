// What cvtmesh computes from one RVD traversal: the CVT integrals, the restricted Delaunay
// triangulation, and the cells themselves for viewing. Each is a PolygonSink; several can share
// one traversal (RestrictedVoronoiDiagram::traverse with a list of sinks).
#pragma once

#include <filesystem>
#include <mutex>
#include <span>
#include <vector>

#include "cvtmesh/rvd.hpp"

namespace cvtmesh {

// Per-seed integrals over its restricted cell R_i with a density ρ linear on each input triangle
// (paper §2, eq. 2-6): mass m_i = ∫ρ, moment ∫ρx, energy ∫ρ‖x − x_i‖².
struct CellIntegrals {
  std::vector<double> mass, energy;
  std::vector<Vec3> moment;
  double total_energy = 0;  // the CVT energy F
  double total_mass = 0;    // with ρ = 1, the area of the surface

  Vec3 centroid(Index seed) const { return (1.0 / mass[seed]) * moment[seed]; }
  // ∂F/∂x_i = 2 (m_i x_i − ∫ρx) = 2 m_i (x_i − c_i), eq. 5.
  std::vector<Vec3> gradient(const std::vector<Vec3>& seeds) const;
};

class CellIntegrator : public PolygonSink {
 public:
  // `density`: one value per input vertex, > 0; empty means ρ = 1. `unit_normals`: one per input
  // triangle, unit_normals(surface) of the diagram's surface, for a caller that integrates over
  // one surface many times (an optimization); empty: each polygon's is computed. Neither is
  // copied: they must outlive the integrator.
  CellIntegrator(const RestrictedVoronoiDiagram& rvd, std::span<const double> density = {},
                 std::span<const Vec3> unit_normals = {});
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  void chunk_done(std::size_t chunk) override;
  void end() override;
  const CellIntegrals& result() const { return result_; }

 private:
  struct Contribution {
    Index seed;
    double mass, energy;
    Vec3 moment;
  };
  // Adds the done chunks that follow those added already, in order, and frees them.
  void add_done_chunks();
  const RestrictedVoronoiDiagram& rvd_;
  std::span<const double> density_;
  std::span<const Vec3> unit_normals_;
  std::vector<std::vector<Contribution>> chunks_;
  std::vector<char> done_;  // per chunk, all its polygons arrived
  std::size_t added_ = 0;   // chunks [0, added_) are in result_
  std::mutex adding_;
  CellIntegrals result_;
};

// Each triangle's unit normal (zero for a degenerate one), for CellIntegrator.
std::vector<Vec3> unit_normals(const TriangleMesh& surface);

// The restricted Delaunay triangulation (paper §4.4): a triangle (i, j, k) for every RVD vertex
// of type C, each triangle once, oriented like the input facet it crosses. Its vertices are the
// seeds, indexed like them (seeds whose cell is empty stay unreferenced).
class RestrictedDelaunayBuilder : public PolygonSink {
 public:
  explicit RestrictedDelaunayBuilder(const RestrictedVoronoiDiagram& rvd) : rvd_(rvd) {}
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  void end() override;
  const TriangleMesh& result() const { return result_; }

 private:
  const RestrictedVoronoiDiagram& rvd_;
  std::vector<std::vector<Triangle>> chunks_;
  TriangleMesh result_;
};

// Collects the cells' polygons, to write the RVD for viewing.
class CellCollector : public PolygonSink {
 public:
  void begin(std::size_t chunks) override;
  void polygon(std::size_t chunk, const RvdPolygon& polygon) override;
  void end() override;
  // Binary PLY: one face per polygon, coloured by its seed (neighbouring cells rarely share a
  // colour), its coordinates multiplied by 2^exponent (for a diagram of a mesh scaled by
  // scaled_by_power_of_two). Written atomically.
  void write_ply(const std::filesystem::path& path, int exponent = 0) const;
  std::size_t polygon_count() const { return seeds_.size(); }

 private:
  struct Chunk {
    std::vector<Index> seeds;
    std::vector<std::uint32_t> sizes;
    std::vector<Vec3> points;
  };
  std::vector<Chunk> chunks_;
  std::vector<Index> seeds_;
  std::vector<std::uint32_t> sizes_;
  std::vector<Vec3> points_;
};

}  // namespace cvtmesh
