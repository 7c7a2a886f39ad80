#include "cvtmesh/sampling.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "geometry/area_sampler.hpp"
#include "geometry/unit_scale.hpp"
#include "io/input_problem.hpp"

namespace cvtmesh {

std::vector<Vec3> sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed) {
  return points_at_unit_scale(mesh, [&](const TriangleMesh& unit) {
    const AreaSampler sampler(unit, seed);
    if (!sampler.has_area()) throw InvalidArgument("cannot sample a surface of zero area");
    std::vector<Vec3> points(count);
    for (std::size_t k = 0; k < count; ++k) points[k] = sampler(k);
    return points;
  });
}

std::vector<Vec3> read_points(const std::filesystem::path& path) {
  if (format_from_extension(path)) {
    TriangleMesh mesh = read_mesh(path);
    return std::move(mesh.vertices);
  }
  std::ifstream in(path);
  if (!in) unreadable_file(path, "cannot open for reading");
  std::vector<Vec3> points;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream words(line);
    Vec3 p;
    std::string extra;
    if (!(words >> p.x >> p.y >> p.z) || (words >> extra))
      throw InputError(path.string() + ": line " + std::to_string(number) +
                       ": expected three numbers \"x y z\"");
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(path.string() + ": line " + std::to_string(number) +
                       ": non-finite coordinate");
    points.push_back(p);
  }
  if (points.empty()) throw InputError(path.string() + ": no points");
  return points;
}

}  // namespace cvtmesh
