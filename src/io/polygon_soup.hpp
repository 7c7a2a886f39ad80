// What cvtmesh's own readers (OFF, PLY) return: points and polygons as the file lists them,
// indices already checked against the vertex count.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <vector>

namespace cvtmesh {

class PolygonSoup {
 public:
  std::vector<std::array<double, 3>> points;
  std::vector<double> vertex_scalar;  // when asked for (read_ply's `with_scalar`)

  std::size_t polygon_count() const { return ends_.size(); }
  // Polygon f's corners, as vertex ids.
  std::span<const std::size_t> polygon(std::size_t f) const {
    const std::size_t begin = f == 0 ? 0 : ends_[f - 1];
    return {corners_.data() + begin, ends_[f] - begin};
  }
  // The polygon being read: its corners one by one, then its end.
  void add_corner(std::size_t id) { corners_.push_back(id); }
  void end_polygon() { ends_.push_back(corners_.size()); }
  void add_polygon(std::initializer_list<std::size_t> ids) {
    corners_.insert(corners_.end(), ids);
    end_polygon();
  }
  void reserve_polygons(std::size_t polygons) {
    ends_.reserve(polygons);
    corners_.reserve(3 * polygons);
  }

 private:
  // All polygons' corners one after the other, and where each polygon's end (a vector per
  // polygon took a third of reading a 270k-triangle PLY in allocations).
  std::vector<std::size_t> corners_;
  std::vector<std::size_t> ends_;
};

}  // namespace cvtmesh
