#include "io/read_off_binary.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "io/input_problem.hpp"

namespace cvtmesh {

namespace {

struct Layout {
  bool little_endian = false;
  bool face_colours = true;  // a colour count (and that many floats) after each face's indices
};

// Geomview's first, then pmp-library's (version 3 on, then before), then the remaining mix.
constexpr std::array<Layout, 4> kLayouts{
    {{false, true}, {false, false}, {true, false}, {true, true}}};

// One attempt at the data in one layout: the soup, or the problem that stopped it.
class Attempt {
 public:
  Attempt(const std::string& bytes, Layout layout) : bytes_(bytes), layout_(layout) {}

  std::optional<PolygonSoup> read(const BinaryOffVertices& header) {
    if (header.dimension) {
      std::int32_t dim = 0;
      if (!next_int(dim)) return std::nullopt;
      if (dim != 3)
        return fail("binary nOFF of dimension " + std::to_string(dim) + " (only 3 is read)");
    }
    std::int32_t vertices = 0, faces = 0, edges = 0;
    if (!next_int(vertices) || !next_int(faces) || !next_int(edges)) return std::nullopt;
    if (vertices < 0 || faces < 0) return fail("binary OFF with a negative vertex or face count");
    // A count beyond what the file holds fails on the missing data; what is reserved for it is
    // capped by the file's size, so a corrupt count allocates no gigabytes.
    const std::size_t words = bytes_.size() / 4;
    PolygonSoup soup;
    soup.points.reserve(std::min<std::size_t>(static_cast<std::size_t>(vertices), words));
    std::vector<float> values(static_cast<std::size_t>(header.floats));
    for (std::int32_t v = 0; v < vertices; ++v) {
      for (float& value : values)
        if (!next_float(value)) return std::nullopt;
      const double w = header.homogeneous ? values[3] : 1.0;
      soup.points.push_back({values[0] / w, values[1] / w, values[2] / w});
    }
    soup.reserve_polygons(std::min<std::size_t>(static_cast<std::size_t>(faces), words / 4));
    for (std::int32_t f = 0; f < faces; ++f) {
      std::int32_t corners = 0;
      if (!next_int(corners)) return std::nullopt;
      if (corners < 0 || static_cast<std::size_t>(corners) > words)
        return fail("binary OFF face " + std::to_string(f) + " announces " +
                    std::to_string(corners) + " corners");
      for (std::int32_t k = 0; k < corners; ++k) {
        std::int32_t id = 0;
        if (!next_int(id)) return std::nullopt;
        if (id < 0 || id >= vertices)
          return fail(vertex_out_of_range("face " + std::to_string(f), std::to_string(id),
                                          static_cast<std::size_t>(vertices)));
        soup.add_corner(static_cast<std::size_t>(id));
      }
      soup.end_polygon();
      if (layout_.face_colours) {
        std::int32_t colours = 0;
        if (!next_int(colours)) return std::nullopt;
        if (colours < 0 || colours > 4)
          return fail("binary OFF face " + std::to_string(f) + " has " + std::to_string(colours) +
                      " colour components (at most 4)");
        float ignored = 0;
        for (std::int32_t c = 0; c < colours; ++c)
          if (!next_float(ignored)) return std::nullopt;
      }
    }
    return soup;
  }

  // Whether the data ended with the faces (bar whitespace, as a final newline).
  bool at_end() const {
    return std::all_of(bytes_.begin() + static_cast<std::ptrdiff_t>(at_), bytes_.end(),
                       [](char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; });
  }
  const std::string& problem() const { return problem_; }

 private:
  bool next_word(std::uint32_t& w) {
    if (bytes_.size() - at_ < 4) {
      problem_ = "truncated binary OFF data: the file ends early";
      return false;
    }
    std::array<std::uint32_t, 4> b{};
    for (int k = 0; k < 4; ++k) b[k] = static_cast<unsigned char>(bytes_[at_ + k]);
    at_ += 4;
    w = layout_.little_endian ? b[3] << 24 | b[2] << 16 | b[1] << 8 | b[0]
                              : b[0] << 24 | b[1] << 16 | b[2] << 8 | b[3];
    return true;
  }
  bool next_int(std::int32_t& i) {
    std::uint32_t w = 0;
    if (!next_word(w)) return false;
    i = static_cast<std::int32_t>(w);
    return true;
  }
  bool next_float(float& f) {
    std::uint32_t w = 0;
    if (!next_word(w)) return false;
    f = std::bit_cast<float>(w);
    return true;
  }
  std::nullopt_t fail(std::string what) {
    problem_ = std::move(what);
    return std::nullopt;
  }

  const std::string& bytes_;
  Layout layout_;
  std::size_t at_ = 0;
  std::string problem_;
};

}  // namespace

PolygonSoup read_off_binary(const std::filesystem::path& path, std::istream& in,
                            const BinaryOffVertices& vertices) {
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) input_problem(path, "read error");
  std::optional<PolygonSoup> geomview;
  std::string geomview_problem;
  for (const Layout& layout : kLayouts) {
    Attempt attempt(bytes, layout);
    std::optional<PolygonSoup> soup = attempt.read(vertices);
    if (soup && attempt.at_end()) return std::move(*soup);
    if (&layout == &kLayouts.front()) {
      geomview = std::move(soup);
      geomview_problem = attempt.problem();
    }
  }
  if (geomview) return std::move(*geomview);
  input_problem(path, geomview_problem);
}

}  // namespace cvtmesh
