// Where a point lies on a set of polylines: at an end exactly, or on a segment to a round-off, and
// how far along, so that the vertices of a large mesh are placed on a long junction at about a
// lookup each (remesh/zip_sheets, remesh/branch_curves).
#pragma once

#include <map>
#include <vector>

#include "cvtmesh/mesh.hpp"
#include "geometry/segment_grid.hpp"

namespace cvtmesh {

class PolylineIndex {
 public:
  // A point is on a segment within `relative` times the segment's length.
  PolylineIndex(const std::vector<std::vector<Vec3>>& polylines, double relative);
  struct At {
    std::size_t polyline;
    double t;  // the arc length to the point over the polyline's, in [0, 1]
    bool end;  // p is the polyline's first or last point exactly
  };
  // Every polyline that ends exactly at p (t 0 at its first point, 1 at its last: a closed one
  // twice); where none does, the polyline of the first segment p lies on, if any.
  std::vector<At> find(const Vec3& p) const;

 private:
  std::map<Vec3, std::vector<At>> ends_;
  std::vector<std::pair<std::size_t, std::size_t>> piece_;  // per grid segment: polyline, step
  std::vector<std::vector<double>> arcs_;                   // per polyline: length to each point
  SegmentGrid grid_;
};

}  // namespace cvtmesh
