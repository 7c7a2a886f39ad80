// Reading goes through our own readers (OFF, OBJ, PLY) and CGAL's for STL; this file adds what
// they leave out: a precise one-line diagnosis of what is wrong with a file, validation, and
// triangulation.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <span>
#include <sstream>
#include <string>
#include <utility>

#include "cvtmesh/io.hpp"
#include "geometry/manifold_defects.hpp"
#include "io/input_problem.hpp"
#include "io/read_obj.hpp"
#include "io/read_off.hpp"
#include "io/read_ply.hpp"

namespace cvtmesh {

namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Polygon = std::span<const std::size_t>;

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
    input_problem(path, "truncated binary STL: the header announces " + std::to_string(count) +
                            " triangles (" + std::to_string(expected) + " bytes), the file has " +
                            std::to_string(size) + " bytes");
}

// An STL file stores each facet's corners apart, and CGAL's reader shares every point that
// recurs. Where that makes a vertex non-manifold (two parts that touch: diplodocus.off written
// as STL came in with 2 non-manifold edges, a worse surface than the file's), each facet there
// keeps a corner of its own, as the file has it, and repair decides what merges (issue 18 item
// 3: split by fans, no part welded to another).
void unweld_nonmanifold_corners(std::vector<Point>& points,
                                std::vector<std::array<std::size_t, 3>>& facets) {
  if (points.size() > std::numeric_limits<Index>::max()) return;  // refused by the caller
  std::vector<Triangle> triangles;
  for (const auto& f : facets)
    triangles.push_back(
        {static_cast<Index>(f[0]), static_cast<Index>(f[1]), static_cast<Index>(f[2])});
  const std::vector<bool> defect =
      find_manifold_defects(points.size(), triangles, {}, false).vertex;
  if (std::none_of(defect.begin(), defect.end(), [](bool d) { return d; })) return;
  std::vector<char> kept(defect.size(), 0);  // the first corner keeps the shared point
  for (auto& f : facets)
    for (std::size_t& v : f)
      if (defect[v] && std::exchange(kept[v], 1)) {
        points.push_back(points[v]);
        v = points.size() - 1;
      }
}

bool read_with_cgal(MeshFormat format, std::istream& in, PolygonSoup& soup, bool verbose) {
  const auto np = CGAL::parameters::verbose(verbose);
  std::vector<Point> points;
  bool ok = false;
  switch (format) {
    case MeshFormat::obj:
    case MeshFormat::off:
    case MeshFormat::ply:
      break;  // read by read_obj, read_off and read_ply, never by CGAL
    case MeshFormat::stl: {
      std::vector<std::array<std::size_t, 3>> triangles;
      ok = CGAL::IO::read_STL(in, points, triangles, np);
      if (ok) unweld_nonmanifold_corners(points, triangles);
      soup.reserve_polygons(triangles.size());
      for (const auto& t : triangles) soup.add_polygon({t[0], t[1], t[2]});
      break;
    }
  }
  soup.points.reserve(points.size());
  for (const Point& p : points) soup.points.push_back({p.x(), p.y(), p.z()});
  return ok;
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

std::string non_finite_vertex(const PolygonSoup& soup) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const auto& [x, y, z] = soup.points[i];
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      std::ostringstream s;
      s << "vertex " << i << " has a non-finite coordinate (" << x << ' ' << y << ' ' << z << ')';
      return s.str();
    }
  }
  return "";
}

std::string out_of_range_index(const PolygonSoup& soup) {
  for (std::size_t f = 0; f < soup.polygon_count(); ++f) {
    for (std::size_t v : soup.polygon(f)) {
      if (v >= soup.points.size()) {
        // Shown as a signed number: CGAL stores a negative (relative) OBJ index wrapped around.
        return vertex_out_of_range("face " + std::to_string(f),
                                   std::to_string(static_cast<long long>(v)), soup.points.size());
      }
    }
  }
  return "";
}

std::string short_face(const PolygonSoup& soup) {
  for (std::size_t f = 0; f < soup.polygon_count(); ++f) {
    if (soup.polygon(f).size() < 3)
      return "face " + std::to_string(f) + " has " + std::to_string(soup.polygon(f).size()) +
             " corners (a face needs at least 3)";
  }
  return "";
}

std::string emptiness(const PolygonSoup& soup) {
  if (soup.points.empty() && soup.polygon_count() == 0) return "empty mesh: no vertices or faces";
  if (soup.points.empty()) return "empty mesh: no vertices";
  if (soup.polygon_count() == 0) return "empty mesh: no faces";
  return "";
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
    PolygonSoup ignored;
    read_with_cgal(format, in, ignored, true);
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

// The triangles of `poly` as a fan around its corner `apex`.
void fan(Polygon poly, std::size_t apex, std::vector<Triangle>& out) {
  const std::size_t n = poly.size();
  for (std::size_t k = 1; k + 1 < n; ++k)
    out.push_back({static_cast<Index>(poly[apex]), static_cast<Index>(poly[(apex + k) % n]),
                   static_cast<Index>(poly[(apex + k + 1) % n])});
}

// A triangle's corners, sorted: the same for a triangle and its copy, either way round.
std::array<Index, 3> corners_of(Triangle t) {
  std::sort(t.begin(), t.end());
  return t;
}

// Where a polygon's fan makes a triangle another face has too (two quads folded along two
// shared edges: fanned from the same corner, both give the triangle of those edges, once either
// way round, a fin on an edge of three triangles, beast.obj of a public test set), the polygon
// is fanned around its next corner that makes none, if one does. The triangles' corners are
// sorted once (a map of them all cost a large quad mesh twice its memory); the few fans made
// again are counted apart.
void refan_duplicates(const PolygonSoup& soup, std::vector<Triangle>& triangles) {
  std::vector<std::array<Index, 3>> sorted(triangles.size());
  std::transform(triangles.begin(), triangles.end(), sorted.begin(), corners_of);
  std::sort(sorted.begin(), sorted.end());
  std::map<std::array<Index, 3>, std::ptrdiff_t> since;  // changes to the counts, by refans
  const auto count = [&](const Triangle& t) {
    const std::array<Index, 3> key = corners_of(t);
    const auto [from, to] = std::equal_range(sorted.begin(), sorted.end(), key);
    const auto change = since.find(key);
    return (to - from) + (change == since.end() ? 0 : change->second);
  };
  std::vector<Triangle> again;
  auto end = triangles.begin();  // past the last polygon's fan: each has its corners less two
  for (std::size_t f = 0; f < soup.polygon_count(); ++f) {
    const Polygon poly = soup.polygon(f);
    const auto own = end;
    end += static_cast<std::ptrdiff_t>(poly.size() - 2);  // read_mesh refuses shorter faces
    if (poly.size() < 4) continue;
    if (std::none_of(own, end, [&](const Triangle& t) { return count(t) > 1; })) continue;
    for (auto t = own; t != end; ++t) --since[corners_of(*t)];
    for (std::size_t apex = 1; apex < poly.size(); ++apex) {
      again.clear();
      fan(poly, apex, again);
      if (std::none_of(again.begin(), again.end(),
                       [&](const Triangle& t) { return count(t) > 0; })) {
        std::copy(again.begin(), again.end(), own);
        break;
      }
    }
    for (auto t = own; t != end; ++t) ++since[corners_of(*t)];
  }
}

TriangleMesh triangulate(const std::filesystem::path& path, PolygonSoup& soup, ReadReport& report) {
  if (soup.points.size() > std::numeric_limits<Index>::max())
    input_problem(path, "too many vertices (" + std::to_string(soup.points.size()) + ")");
  TriangleMesh mesh;
  mesh.vertices.reserve(soup.points.size());
  for (const auto& [x, y, z] : soup.points) mesh.vertices.push_back({x, y, z});
  report.polygons_in_file = soup.polygon_count();
  mesh.triangles.reserve(soup.polygon_count());
  for (std::size_t f = 0; f < soup.polygon_count(); ++f) {
    const Polygon poly = soup.polygon(f);
    // Fan split: exact for triangles and convex polygons, the common case in mesh files.
    if (poly.size() > 3) ++report.polygons_split;
    fan(poly, 0, mesh.triangles);
  }
  if (report.polygons_split > 0) refan_duplicates(soup, mesh.triangles);
  return mesh;
}

}  // namespace

TriangleMesh read_mesh(const std::filesystem::path& path, ReadReport* report) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) unreadable_file(path, "no such file");
  if (std::filesystem::is_directory(status))
    unreadable_file(path, "is a directory, not a mesh file");
  const auto format = format_from_extension(path);
  if (!format)
    input_problem(path, "unknown extension '" + path.extension().string() +
                            "' (expected .obj, .off, .ply or .stl)");
  std::ifstream in(path, std::ios::binary);
  if (!in) unreadable_file(path, std::string("cannot open for reading: ") + std::strerror(errno));
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size == 0) input_problem(path, "file is empty");
  if (*format == MeshFormat::stl) check_binary_stl_size(path, in, size);

  PolygonSoup soup;
  bool parsed = false;
  if (*format != MeshFormat::stl) {
    soup = *format == MeshFormat::off   ? read_off(path, in, size)
           : *format == MeshFormat::obj ? read_obj(path, in)
                                        : read_ply(path, in, size);
    parsed = true;
  } else {
    try {
      parsed = read_with_cgal(*format, in, soup, false);
    } catch (const std::exception& e) {
      input_problem(path, "malformed " + format_name(*format) + " data (" + e.what() + ")");
    }
  }
  if (parsed) {
    for (const std::string& problem :
         {non_finite_vertex(soup), out_of_range_index(soup), short_face(soup), emptiness(soup)})
      if (!problem.empty()) input_problem(path, problem);
  } else {
    // A reader that stopped early leaves a partial soup (its last face may be half-read), so
    // only the problems that caused the stop are looked for.
    if (std::string token = find_non_finite_token(path); !token.empty()) input_problem(path, token);
    if (std::string problem = out_of_range_index(soup); !problem.empty())
      input_problem(path, problem);
    const std::string why = cgal_diagnosis(*format, path);
    if (std::string problem = emptiness(soup);
        !problem.empty() && (why.empty() || why.find("empty") != std::string::npos))
      input_problem(path, problem);
    input_problem(path, "malformed or truncated " + format_name(*format) + " data" +
                            (why.empty() ? "" : " (" + why + ")"));
  }
  ReadReport local;
  TriangleMesh mesh = triangulate(path, soup, report ? *report : local);
  return mesh;
}

}  // namespace cvtmesh
