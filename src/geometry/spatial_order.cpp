#include "geometry/spatial_order.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <numeric>

namespace cvtmesh {

std::vector<Index> spatial_order(const std::vector<Vec3>& points) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> cgal_points;
  cgal_points.reserve(points.size());
  for (const Vec3& p : points) cgal_points.emplace_back(p.x, p.y, p.z);
  // The adapter's keys are std::size_t: so are the indices sorted.
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using Traits =
      CGAL::Spatial_sort_traits_adapter_3<Kernel,
                                          CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  CGAL::hilbert_sort(order.begin(), order.end(),
                     Traits(CGAL::make_property_map(cgal_points.data())));
  return std::vector<Index>(order.begin(), order.end());
}

}  // namespace cvtmesh
