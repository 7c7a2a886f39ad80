// The public entry points: remesh() works on the input scaled to about unit size.
#include "cvtmesh/remesh.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "cvtmesh/errors.hpp"
#include "geometry/even_spacing.hpp"
#include "geometry/orient_triangles.hpp"
#include "geometry/triangle_sides.hpp"
#include "remesh/by_component.hpp"
#include "remesh/pipeline.hpp"
#include "sizing/size_field.hpp"
#include "system/memory_budget.hpp"

namespace cvtmesh {

namespace {

// Settings in the units of a mesh scaled by 2^exponent.
RemeshSettings scaled_settings(RemeshSettings s, int exponent) {
  s.edge_length = std::ldexp(s.edge_length, exponent);
  s.features.scale = std::ldexp(s.features.scale, exponent);
  for (Vec3& p : s.initial_seeds) p = scaled_by_power_of_two(p, exponent);
  SizingSettings& z = s.sizing;
  for (double& h : z.edge_lengths) h = std::ldexp(h, exponent);
  if (z.edge_length_at)
    z.edge_length_at = [f = std::move(z.edge_length_at), exponent](const Vec3& p) {
      return std::ldexp(f(scaled_by_power_of_two(p, -exponent)), exponent);
    };
  z.min_edge_length = std::ldexp(z.min_edge_length, exponent);
  z.max_edge_length = std::ldexp(z.max_edge_length, exponent);
  return s;
}

}  // namespace

std::size_t requested_vertex_count(const TriangleMesh& mesh, const RemeshSettings& s) {
  const int exponent = size_exponent(mesh);
  if (exponent != 0)
    return requested_vertex_count(scaled_by_power_of_two(mesh, -exponent),
                                  scaled_settings(s, -exponent));
  check_output_size(s);
  std::optional<SizeField> field;
  std::optional<TriangleMesh> split;  // where the field is made, if not on `mesh`
  if (s.sizing.active() && s.vertices == 0) {
    // As remesh_unit makes it: an adaptive sizing narrows at the gaps between features.
    std::optional<Features> features;
    if (s.sizing.adaptive > 0) {
      FeatureSettings at_scale = s.features;
      at_scale.scale = scale_before_sizing(mesh, s);
      features = detect_features(mesh, at_scale);
    }
    field = make_size_field(mesh, {}, s, features ? &*features : nullptr, &split);
  }
  return unit_vertex_count(mesh, s, field ? &*field : nullptr);
}

double requested_edge_length(const TriangleMesh& mesh, const RemeshSettings& settings) {
  return edge_length_for(surface_area(mesh), requested_vertex_count(mesh, settings));
}

RemeshResult remesh(const TriangleMesh& input, const RemeshSettings& settings) {
  // Output triangles take the orientation of the input under them: an input partly listed the
  // other way round is remeshed as repair_mesh orients it (geometry/orient_triangles.hpp).
  // The input's sides, sorted, serve the components' split too (igea.ply at 1k: 4% of the
  // remesh, on the serial path, when each sorted its own).
  std::vector<TriangleSide> sides = sorted_sides(input);
  if (const std::vector<std::size_t> flips = triangles_to_flip(input, sides); !flips.empty()) {
    TriangleMesh oriented = input;
    flip_triangles(oriented, flips);
    std::vector<TriangleSide>().swap(sides);
    return remesh(oriented, settings);
  }
  // Issue 22: the work is done on the input scaled by a power of two to about unit size, and
  // the output scaled back, both exactly; a shape in any units gives the same output up to the
  // scale.
  // A job that cannot fit fails now, before any work, when its size is known without the
  // sizing's lengths (remesh_unit checks again with them).
  if (!settings.initial_seeds.empty() || settings.vertices > 0 || !settings.sizing.active())
    check_memory_for(input.triangles.size(), settings.initial_seeds.empty()
                                                 ? requested_vertex_count(input, settings)
                                                 : settings.initial_seeds.size());
  const int exponent = size_exponent(input);
  // Scaling keeps the connectivity: the sides stay those of the scaled input.
  RemeshResult r =
      exponent == 0 ? remesh_by_component(input, settings, std::move(sides))
                    : remesh_by_component(scaled_by_power_of_two(input, -exponent),
                                          scaled_settings(settings, -exponent), std::move(sides));
  // Cells that wrap around parts thinner than the spacing everywhere meet in no Voronoi vertex
  // on the surface: no triangle, however the count grew (a torus whose tube is a fifth of the
  // spacing around). An empty file would be no answer.
  if (r.mesh.triangles.empty() && !r.time_limit_reached && !input.triangles.empty())
    throw InvalidArgument(
        "no output triangle: the surface is thinner than the spacing of the vertices asked for "
        "(cells wrap around it); ask for more vertices");
  if (exponent == 0) return r;
  r.mesh = scaled_by_power_of_two(std::move(r.mesh), exponent);
  if (r.hausdorff) r.hausdorff = scaled_by_power_of_two(*r.hausdorff, exponent);
  return r;
}

}  // namespace cvtmesh
