// Reading goes through CGAL's polygon-soup readers; this file adds what they leave out: a
// precise one-line diagnosis of what is wrong with a file, validation, and triangulation.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"

namespace cvtmesh {

namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Polygon = std::vector<std::size_t>;

struct Soup {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem) {
  throw InputError(path.string() + ": " + problem);
}

// A binary STL is an 80-byte header, a uint32 triangle count, then 50 bytes per triangle. CGAL
// does not say why a short file fails, so check the size here.
void check_binary_stl_size(const std::filesystem::path& path, std::istream& in,
                           std::uintmax_t size) {
  char head[84];
  if (!in.read(head, sizeof head)) {
    in.clear();
    in.seekg(0);
    return;  // too short to be binary: let the ASCII reader judge it
  }
  in.seekg(0);
  if (std::string(head, 5) == "solid") return;  // ASCII, or a binary one CGAL will sort out
  std::uint32_t count;
  std::memcpy(&count, head + 80, 4);
  const std::uintmax_t expected = 84 + 50 * std::uintmax_t{count};
  if (size < expected)
    fail(path, "truncated binary STL: the header announces " + std::to_string(count) +
                   " triangles (" + std::to_string(expected) + " bytes), the file has " +
                   std::to_string(size) + " bytes");
}

bool read_with_cgal(MeshFormat format, std::istream& in, Soup& soup) {
  const auto np = CGAL::parameters::verbose(false);
  switch (format) {
    case MeshFormat::obj:
      return CGAL::IO::read_OBJ(in, soup.points, soup.polygons, np);
    case MeshFormat::off:
      return CGAL::IO::read_OFF(in, soup.points, soup.polygons, np);
    case MeshFormat::ply:
      return CGAL::IO::read_PLY(in, soup.points, soup.polygons, np);
    case MeshFormat::stl: {
      std::vector<std::array<std::size_t, 3>> triangles;
      const bool ok = CGAL::IO::read_STL(in, soup.points, triangles, np);
      for (const auto& t : triangles) soup.polygons.emplace_back(t.begin(), t.end());
      return ok;
    }
  }
  return false;
}

std::string format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::obj: return "OBJ";
    case MeshFormat::off: return "OFF";
    case MeshFormat::ply: return "PLY";
    case MeshFormat::stl: return "STL";
  }
  return "?";
}

// What is wrong with what was read, or "" when it is a valid polygon soup.
std::string validation_problem(const Soup& soup) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      std::ostringstream s;
      s << "vertex " << i << " has a non-finite coordinate (" << p.x() << ' ' << p.y() << ' '
        << p.z() << ')';
      return s.str();
    }
  }
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const Polygon& poly = soup.polygons[f];
    if (poly.size() < 3)
      return "face " + std::to_string(f) + " has " + std::to_string(poly.size()) +
             " corners (a face needs at least 3)";
    for (std::size_t v : poly) {
      if (v >= soup.points.size()) {
        // OBJ indices are 1-based; CGAL stores negative (relative) ones wrapped around.
        const long long shown = static_cast<long long>(v);
        return "face " + std::to_string(f) + " references vertex " + std::to_string(shown) +
               ", out of range (the file has " + std::to_string(soup.points.size()) +
               " vertices)";
      }
    }
  }
  if (soup.points.empty()) return "empty mesh: no vertices";
  if (soup.polygons.empty()) return "empty mesh: no faces";
  return "";
}

// ASCII readers stop at the first token they cannot parse as a number, without saying which.
// Find a "nan"/"inf" token, the usual culprit, to name it and its line.
std::string find_non_finite_token(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (line.find('\0') != std::string::npos) return "";  // binary data: not a text file
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      if (w[0] == '#') break;
      std::string lower;
      for (char c : w) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (lower[0] == '+' || lower[0] == '-') lower.erase(0, 1);
      if (lower == "nan" || lower == "inf" || lower == "infinity")
        return "non-finite coordinate '" + w + "' on line " + std::to_string(number);
    }
  }
  return "";
}

TriangleMesh triangulate(const std::filesystem::path& path, Soup& soup, ReadReport& report) {
  if (soup.points.size() > std::numeric_limits<Index>::max())
    fail(path, "too many vertices (" + std::to_string(soup.points.size()) + ")");
  TriangleMesh mesh;
  mesh.vertices.reserve(soup.points.size());
  for (const Point& p : soup.points) mesh.vertices.push_back({p.x(), p.y(), p.z()});
  report.polygons_in_file = soup.polygons.size();
  mesh.triangles.reserve(soup.polygons.size());
  for (const Polygon& poly : soup.polygons) {
    // Fan split: exact for triangles and convex polygons, the common case in mesh files.
    if (poly.size() > 3) ++report.polygons_split;
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)
      mesh.triangles.push_back({static_cast<Index>(poly[0]), static_cast<Index>(poly[k]),
                                static_cast<Index>(poly[k + 1])});
  }
  return mesh;
}

}  // namespace

TriangleMesh read_mesh(const std::filesystem::path& path, ReadReport* report) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) fail(path, "no such file");
  if (std::filesystem::is_directory(status)) fail(path, "is a directory, not a mesh file");
  const auto format = format_from_extension(path);
  if (!format)
    fail(path, "unknown extension '" + path.extension().string() +
                   "' (expected .obj, .off, .ply or .stl)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open for reading: ") + std::strerror(errno));
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size == 0) fail(path, "file is empty");
  if (*format == MeshFormat::stl) check_binary_stl_size(path, in, size);

  Soup soup;
  bool parsed = false;
  try {
    parsed = read_with_cgal(*format, in, soup);
  } catch (const std::exception& e) {
    fail(path, "malformed " + format_name(*format) + " data (" + e.what() + ")");
  }
  // A soup read in full can still be invalid; a partial one usually says why parsing stopped.
  if (std::string problem = validation_problem(soup); !problem.empty()) {
    if (parsed || problem.starts_with("vertex") || problem.starts_with("face")) fail(path, problem);
  }
  if (!parsed) {
    if (*format != MeshFormat::ply || soup.points.empty()) {
      if (std::string token = find_non_finite_token(path); !token.empty()) fail(path, token);
    }
    if (soup.points.empty() && soup.polygons.empty() && *format != MeshFormat::ply)
      fail(path, "empty mesh: no vertices or faces found");
    fail(path, "malformed or truncated " + format_name(*format) + " data");
  }
  ReadReport local;
  TriangleMesh mesh = triangulate(path, soup, report ? *report : local);
  return mesh;
}

}  // namespace cvtmesh
