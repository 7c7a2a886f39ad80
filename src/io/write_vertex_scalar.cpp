// A mesh with one scalar per vertex, for viewing (cvtmesh lfs).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "cvtmesh/io.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_out.hpp"

namespace cvtmesh {

namespace {

struct Rgb {
  std::uint8_t r, g, b;
};

// t in [0, 1]: red, yellow, green, blue.
Rgb ramp(double t) {
  const double x = std::clamp(t, 0.0, 1.0) * 3;
  const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(255 * v)); };
  if (x < 1) return {255, byte(x), 0};
  if (x < 2) return {byte(2 - x), 255, 0};
  return {0, byte(3 - x), byte(x - 2)};
}

}  // namespace

void write_ply_with_vertex_scalar(const std::filesystem::path& path, const TriangleMesh& mesh,
                                  const std::vector<double>& values, const char* name) {
  double lo = INFINITY, hi = 0;
  for (const double v : values)
    if (v > 0 && std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  const double span = hi > lo ? std::log(hi / lo) : 1;
  io::write_atomically(path, true, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment cvtmesh: " << name
        << " per vertex, coloured red (smallest) to blue (largest) on a log scale\n"
        << fmt::format("element vertex {}\n", mesh.vertices.size())
        << "property double x\nproperty double y\nproperty double z\n"
        << "property float " << name << '\n'
        << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
        << fmt::format("element face {}\n", mesh.triangles.size())
        << "property list uchar int vertex_indices\nend_header\n";
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const Vec3& p = mesh.vertices[v];
      io::put(out, p.x), io::put(out, p.y), io::put(out, p.z);
      io::put(out, static_cast<float>(values[v]));
      const Rgb c = values[v] > 0 ? ramp(std::log(values[v] / lo) / span) : Rgb{128, 128, 128};
      io::put(out, c.r), io::put(out, c.g), io::put(out, c.b);
    }
    for (const Triangle& t : mesh.triangles) {
      io::put(out, std::uint8_t{3});
      for (const Index v : t) io::put(out, static_cast<std::int32_t>(v));
    }
    return true;
  });
}

}  // namespace cvtmesh
