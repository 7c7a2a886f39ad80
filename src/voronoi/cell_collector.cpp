#include <fmt/core.h>

#include "cvtmesh/rvd_consumers.hpp"
#include "geometry/random.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_out.hpp"

namespace cvtmesh {

void CellCollector::begin(std::size_t chunks) {
  chunks_.assign(chunks, {});
}

void CellCollector::polygon(std::size_t chunk, const RvdPolygon& poly) {
  Chunk& c = chunks_[chunk];
  c.seeds.push_back(poly.seed);
  c.sizes.push_back(static_cast<std::uint32_t>(poly.vertices.size()));
  for (const RvdVertex& v : poly.vertices) c.points.push_back(v.point);
}

void CellCollector::end() {
  seeds_.clear(), sizes_.clear(), points_.clear();
  for (const Chunk& c : chunks_) {
    seeds_.insert(seeds_.end(), c.seeds.begin(), c.seeds.end());
    sizes_.insert(sizes_.end(), c.sizes.begin(), c.sizes.end());
    points_.insert(points_.end(), c.points.begin(), c.points.end());
  }
  chunks_.clear();
}

using io::put;

void CellCollector::write_ply(const std::filesystem::path& path, int exponent) const {
  io::write_atomically(path, true, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment cvtmesh restricted Voronoi cells\n"
        << fmt::format("element vertex {}\n", points_.size())
        << "property double x\nproperty double y\nproperty double z\n"
        << fmt::format("element face {}\n", sizes_.size())
        << "property list uchar int vertex_indices\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (const Vec3& point : points_) {
      const Vec3 p = scaled_by_power_of_two(point, exponent);
      put(out, p.x), put(out, p.y), put(out, p.z);
    }
    std::int32_t next = 0;
    for (std::size_t f = 0; f < sizes_.size(); ++f) {
      if (sizes_[f] > 255) return false;  // the list length is a uchar
      put(out, static_cast<std::uint8_t>(sizes_[f]));
      for (std::uint32_t k = 0; k < sizes_[f]; ++k) put(out, next++);
      // A pseudo-random colour per seed: neighbouring cells rarely look alike.
      const std::uint64_t h = mix64(seeds_[f]);
      put(out, static_cast<std::uint8_t>(64 + (h & 0xbf)));
      put(out, static_cast<std::uint8_t>(64 + ((h >> 8) & 0xbf)));
      put(out, static_cast<std::uint8_t>(64 + ((h >> 16) & 0xbf)));
    }
    return true;
  });
}

}  // namespace cvtmesh
