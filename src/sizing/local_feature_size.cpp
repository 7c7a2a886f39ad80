// The local feature size (paper §4.1): distances from the surface to the poles of a dense
// sample, which approximate the medial axis, bounded by rays along the normals; then graded.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/sizing.hpp"
#include "geometry/area_sampler.hpp"
#include "geometry/point_tree.hpp"
#include "geometry/unit_vector.hpp"
#include "geometry/vertex_normals.hpp"
#include "sizing/gradation.hpp"
#include "sizing/normal_rays.hpp"
#include "sizing/poles.hpp"

namespace cvtmesh {

namespace {

// The vertices with a normal (`normal`, unit_vertex_normals), and `count` area-uniform samples
// with their triangles' normals.
std::vector<SurfaceSample> surface_samples(const TriangleMesh& mesh,
                                           const std::vector<Vec3>& normal, std::size_t count,
                                           std::uint64_t seed) {
  std::vector<Vec3> face_normal(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto [a, b, c] = mesh.corners(t);
    face_normal[t] = unit_normal(a, b, c);
  }
  const AreaSampler sampler(mesh, seed);
  std::vector<SurfaceSample> samples(count);
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t k) {
    const AreaSampler::Sample s = sampler.sample(k);
    samples[k] = {s.point, face_normal[s.triangle]};
  });
  for (Index v = 0; v < mesh.vertices.size(); ++v)
    if (dot(normal[v], normal[v]) > 0) samples.push_back({mesh.vertices[v], normal[v]});
  return samples;
}

}  // namespace

std::vector<double> local_feature_size(const TriangleMesh& given, const LfsSettings& settings) {
  if (!(settings.gradation >= 0) || !std::isfinite(settings.gradation))
    throw InvalidArgument("the gradation must be a number >= 0");
  // At about unit size (see size_exponent): distances neither overflow nor underflow.
  const int exponent = size_exponent(given);
  const TriangleMesh mesh = scaled_by_power_of_two(given, -exponent);
  if (!(surface_area(mesh) > 0)) throw InvalidArgument("the surface has no area");
  const std::vector<Vec3> normals = unit_vertex_normals(mesh);
  const std::vector<Vec3> poles =
      sample_poles(surface_samples(mesh, normals, settings.samples, settings.seed));
  // No pole (a flat surface, whose medial axis is at infinity): the size of the whole.
  const double cap = bounding_box(mesh).diagonal();
  std::vector<double> lfs(mesh.vertices.size(), cap);
  if (!poles.empty()) {
    const PointTree tree(poles);
    tbb::parallel_for(std::size_t{0}, lfs.size(), [&](std::size_t v) {
      lfs[v] = std::min(cap, distance(mesh.vertices[v], poles[tree(mesh.vertices[v])]));
    });
  }
  bound_by_normal_rays(mesh, normals, lfs);
  if (settings.features) lfs = capped_by_feature_gaps(mesh, *settings.features, std::move(lfs));
  if (settings.gradation > 0) lfs = graded(mesh, std::move(lfs), settings.gradation);

  const std::vector<bool> used = used_vertices(mesh);
  for (std::size_t v = 0; v < lfs.size(); ++v) lfs[v] = used[v] ? std::ldexp(lfs[v], exponent) : 0;
  return lfs;
}

}  // namespace cvtmesh
