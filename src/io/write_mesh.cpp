#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <limits>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "io/atomic_file.hpp"

namespace cvtmesh {

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh) {
  const auto format = format_from_extension(path);
  if (!format)
    throw InvalidArgument(path.string() + ": unknown output extension '" +
                          path.extension().string() + "' (expected .obj, .off, .ply or .stl)");
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.emplace_back(v.x, v.y, v.z);
  const auto& triangles = mesh.triangles;

  // ASCII coordinates with 17 significant digits read back to the same doubles.
  const auto exact_text =
      CGAL::parameters::stream_precision(std::numeric_limits<double>::max_digits10);
  const bool binary = *format == MeshFormat::ply || *format == MeshFormat::stl;
  io::write_atomically(path, binary, [&](std::ostream& out) {
    switch (*format) {
      case MeshFormat::obj:
        return CGAL::IO::write_OBJ(out, points, triangles, exact_text);
      case MeshFormat::off:
        return CGAL::IO::write_OFF(out, points, triangles, exact_text);
      case MeshFormat::ply:
        CGAL::IO::set_binary_mode(out);
        return CGAL::IO::write_PLY(out, points, triangles);
      case MeshFormat::stl:
        CGAL::IO::set_binary_mode(out);
        return CGAL::IO::write_STL(out, points, triangles);
    }
    return false;
  });
}

}  // namespace cvtmesh
