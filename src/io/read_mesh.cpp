// Reading goes through CGAL's polygon-soup readers; this file adds what they leave out: a
// precise one-line diagnosis of what is wrong with a file, validation, and triangulation.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <mutex>
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

// CGAL 5.5's PLY reader adds each property to the last element declared, without checking that
// there is one: a property line before the first element line writes out of bounds (found by
// fuzzing). Such a header is refused here.
void check_ply_header(const std::filesystem::path& path, std::istream& in) {
  std::string line;
  bool element = false;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") break;
    if (keyword == "element") element = true;
    if (keyword == "property" && !element)
      fail(path, "malformed PLY header: line " + std::to_string(number) +
                     " declares a property before any element");
  }
  in.clear();
  in.seekg(0);
}

bool read_with_cgal(MeshFormat format, std::istream& in, Soup& soup, bool verbose) {
  const auto np = CGAL::parameters::verbose(verbose);
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
    case MeshFormat::obj:
      return "OBJ";
    case MeshFormat::off:
      return "OFF";
    case MeshFormat::ply:
      return "PLY";
    case MeshFormat::stl:
      return "STL";
  }
  return "?";
}

std::string non_finite_vertex(const Soup& soup) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      std::ostringstream s;
      s << "vertex " << i << " has a non-finite coordinate (" << p.x() << ' ' << p.y() << ' '
        << p.z() << ')';
      return s.str();
    }
  }
  return "";
}

std::string out_of_range_index(const Soup& soup) {
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    for (std::size_t v : soup.polygons[f]) {
      if (v >= soup.points.size()) {
        // Shown as a signed number: CGAL stores a negative (relative) OBJ index wrapped around.
        return "face " + std::to_string(f) + " references vertex " +
               std::to_string(static_cast<long long>(v)) + ", out of range (the file has " +
               std::to_string(soup.points.size()) + " vertices)";
      }
    }
  }
  return "";
}

std::string short_face(const Soup& soup) {
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    if (soup.polygons[f].size() < 3)
      return "face " + std::to_string(f) + " has " + std::to_string(soup.polygons[f].size()) +
             " corners (a face needs at least 3)";
  }
  return "";
}

std::string emptiness(const Soup& soup) {
  if (soup.points.empty() && soup.polygons.empty()) return "empty mesh: no vertices or faces";
  if (soup.points.empty()) return "empty mesh: no vertices";
  if (soup.polygons.empty()) return "empty mesh: no faces";
  return "";
}

// CGAL's read_OFF keeps its scanner quiet; drive the scanner the same way, verbosely, so that it
// names the problem (bad index, premature end, ...). Diagnosis only: the data are discarded.
void scan_off_verbosely(std::istream& in) {
  CGAL::File_scanner_OFF scanner(in, true);
  for (std::size_t i = 0; in && i < scanner.size_of_vertices(); ++i) {
    double x, y, z, w, nx, ny, nz;
    unsigned char r, g, b;
    scanner.scan_vertex(x, y, z, w);
    if (scanner.has_normals()) scanner.scan_normal(nx, ny, nz);
    if (scanner.has_vcolors()) scanner.scan_color(r, g, b);
    if (scanner.has_textures()) scanner.scan_texture(x, y);
    if (in) scanner.skip_to_next_vertex(i);
  }
  for (std::size_t f = 0; in && f < scanner.size_of_facets(); ++f) {
    std::size_t corners = 0, id = 0;
    scanner.scan_facet(corners, f);
    for (std::size_t k = 0; in && k < corners; ++k) scanner.scan_facet_vertex_index(id, k + 1, f);
  }
}

// CGAL's readers say why they fail only on std::cerr, in verbose mode. After a quiet read has
// failed, read again verbosely with the standard streams captured, and keep CGAL's last line.
// Only failing reads get here, and the mutex keeps two of them from mixing their captures.
std::string cgal_diagnosis(MeshFormat format, const std::filesystem::path& path) {
  static std::mutex capture_mutex;
  const std::lock_guard lock(capture_mutex);
  std::ostringstream captured;
  std::streambuf* const err = std::cerr.rdbuf(captured.rdbuf());
  std::streambuf* const out = std::cout.rdbuf(captured.rdbuf());
  try {
    std::ifstream in(path, std::ios::binary);
    if (format == MeshFormat::off) {
      scan_off_verbosely(in);
    } else {
      Soup ignored;
      read_with_cgal(format, in, ignored, true);
    }
  } catch (const std::exception&) {
  }
  std::cerr.rdbuf(err);
  std::cout.rdbuf(out);
  std::istringstream lines(captured.str());
  std::string line, last;
  while (std::getline(lines, line)) {
    line.erase(0, line.find_first_not_of(" \t"));
    if (line.empty() || line.ends_with("::") || line.starts_with("NOTE")) continue;
    last = line;
  }
  if (const auto at = last.find("error: "); at != std::string::npos) last.erase(0, at + 7);
  if (const auto at = last.find("error:"); at != std::string::npos) last.erase(0, at + 6);
  last.erase(0, last.find_first_not_of(' '));
  return last;
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
  if (*format == MeshFormat::ply) check_ply_header(path, in);

  Soup soup;
  bool parsed = false;
  try {
    parsed = read_with_cgal(*format, in, soup, false);
  } catch (const std::exception& e) {
    fail(path, "malformed " + format_name(*format) + " data (" + e.what() + ")");
  }
  if (parsed) {
    for (const std::string& problem :
         {non_finite_vertex(soup), out_of_range_index(soup), short_face(soup), emptiness(soup)})
      if (!problem.empty()) fail(path, problem);
  } else {
    // A reader that stopped early leaves a partial soup (its last face may be half-read), so
    // only the problems that caused the stop are looked for.
    if (std::string token = find_non_finite_token(path); !token.empty()) fail(path, token);
    if (std::string problem = out_of_range_index(soup); !problem.empty()) fail(path, problem);
    const std::string why = cgal_diagnosis(*format, path);
    if (std::string problem = emptiness(soup);
        !problem.empty() && (why.empty() || why.find("empty") != std::string::npos))
      fail(path, problem);
    fail(path, "malformed or truncated " + format_name(*format) + " data" +
                   (why.empty() ? "" : " (" + why + ")"));
  }
  ReadReport local;
  TriangleMesh mesh = triangulate(path, soup, report ? *report : local);
  return mesh;
}

}  // namespace cvtmesh
