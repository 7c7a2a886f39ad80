// OFF as Geomview specifies it: a header keyword whose prefixes say what each vertex line holds
// besides its coordinates, the counts, the vertices, then faces "k i1 .. ik [colour]". Only
// positions and faces are kept; everything after the coordinates and indices is skipped, so a
// colour of any width is harmless.
#include "io/read_off.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include "io/input_problem.hpp"
#include "io/read_off_binary.hpp"
#include "io/text_tokens.hpp"

namespace cvtmesh {

namespace {

struct Header {
  bool texture = false;      // ST: 2 texture coordinates (3 if homogeneous) per vertex
  bool colour = false;       // C: a colour per vertex
  bool normal = false;       // N: a normal per vertex
  bool homogeneous = false;  // 4: x y z w
  bool dimension = false;    // n: the dimension is given before the counts
  bool binary = false;
};

class OffReader {
 public:
  OffReader(const std::filesystem::path& path, std::istream& in, std::uintmax_t file_size)
      : path_(path), in_(in), file_size_(file_size) {}

  PolygonSoup read() {
    if (!next_line()) fail("empty OFF file");
    Header header;
    if (!tokens_.empty() && parse_keyword(tokens_.front(), header)) {
      tokens_.erase(tokens_.begin());
      if (!tokens_.empty() && tokens_.front() == "BINARY") {
        header.binary = true;
        tokens_.erase(tokens_.begin());
      }
    } else if (tokens_.empty() || !is_integer(tokens_.front())) {
      fail_here("not an OFF file: expected the keyword OFF, got '" + first_token() + "'");
    }
    if (header.binary) {
      const int h = header.homogeneous ? 1 : 0;
      return read_off_binary(path_, in_,
                             {3 + h + (header.normal ? 3 + h : 0) + (header.colour ? 4 : 0) +
                                  (header.texture ? 2 + h : 0),
                              header.homogeneous, header.dimension});
    }
    if (header.dimension) {
      const std::uint64_t dim = count("the dimension");
      if (dim != 3) fail_here("nOFF of dimension " + std::to_string(dim) + " (only 3 is read)");
    }
    const std::uint64_t vertices = count("the vertex count");
    const std::uint64_t faces = count("the face count");
    PolygonSoup soup;
    soup.points.reserve(capped(vertices));
    for (std::uint64_t v = 0; v < vertices; ++v) {
      if (!next_line()) truncated(vertices, faces, v, 0);
      soup.points.push_back(vertex(v, header.homogeneous));
    }
    soup.reserve_polygons(capped(faces));
    for (std::uint64_t f = 0; f < faces; ++f) {
      if (!next_line()) truncated(vertices, faces, vertices, f);
      face(f, vertices, soup);
    }
    return soup;
  }

 private:
  // [ST][C][N][4][n]OFF, in that order.
  static bool parse_keyword(std::string_view word, Header& header) {
    if (!word.ends_with("OFF")) return false;
    word.remove_suffix(3);
    auto take = [&word](std::string_view prefix) {
      if (!word.starts_with(prefix)) return false;
      word.remove_prefix(prefix.size());
      return true;
    };
    header.texture = take("ST");
    header.colour = take("C");
    header.normal = take("N");
    header.homogeneous = take("4");
    header.dimension = take("n");
    return word.empty();
  }

  static bool is_integer(std::string_view token) {
    return !token.empty() &&
           std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
  }

  // The next line with content, comments removed, split into tokens_. False at the end.
  bool next_line() {
    while (std::getline(in_, line_)) {
      ++line_number_;
      if (const auto hash = line_.find('#'); hash != std::string::npos) line_.erase(hash);
      split_words(line_, tokens_);
      if (!tokens_.empty()) return true;
    }
    if (in_.bad()) fail("read error");
    return false;
  }

  // A count from the current line, or from the next one once this line is used up: Geomview
  // allows the counts on the keyword's line or on their own.
  std::uint64_t count(const std::string& what) {
    if (used_ == tokens_.size()) {
      if (!next_line()) fail("truncated OFF data: the file ends before " + what);
      used_ = 0;
    }
    const std::string_view token = tokens_[used_++];
    const std::optional<std::uint64_t> value = text_count(token);
    if (!value) fail_here(what + " '" + std::string(token) + "' is not a non-negative integer");
    return *value;
  }

  std::array<double, 3> vertex(std::uint64_t v, bool homogeneous) {
    const std::size_t needed = homogeneous ? 4 : 3;
    if (tokens_.size() < needed)
      fail_here("vertex " + std::to_string(v) + " has " + std::to_string(tokens_.size()) +
                " coordinates (expected " + std::to_string(needed) + ")");
    double x[4];
    for (std::size_t k = 0; k < needed; ++k) x[k] = number(tokens_[k], v);
    if (homogeneous) return {x[0] / x[3], x[1] / x[3], x[2] / x[3]};
    return {x[0], x[1], x[2]};
  }

  double number(std::string_view token, std::uint64_t v) {
    const std::optional<double> value = text_double(token);
    if (!value)
      fail_here("vertex " + std::to_string(v) + ": '" + std::string(token) + "' is not a number");
    return *value;
  }

  // Face f, added to `soup`.
  void face(std::uint64_t f, std::uint64_t vertices, PolygonSoup& soup) {
    long long corners = index(tokens_[0], f);
    if (corners < 0 || static_cast<std::size_t>(corners) > tokens_.size() - 1)
      fail_here("face " + std::to_string(f) + " announces " + std::string(tokens_[0]) +
                " corners, its line has " + std::to_string(tokens_.size() - 1) + " more numbers");
    for (std::size_t k = 0; k < static_cast<std::size_t>(corners); ++k) {
      const long long id = index(tokens_[k + 1], f);
      if (id < 0 || static_cast<std::uint64_t>(id) >= vertices) out_of_range(f, id, vertices);
      soup.add_corner(static_cast<std::size_t>(id));
    }
    soup.end_polygon();
  }

  long long index(std::string_view token, std::uint64_t f) {
    const std::optional<long long> value = text_integer(token);
    if (!value)
      fail_here("face " + std::to_string(f) + ": '" + std::string(token) + "' is not an integer");
    return *value;
  }

  // A count from the header reserves no more than the file could hold, so that a corrupt count
  // fails on the missing data instead of allocating gigabytes.
  std::size_t capped(std::uint64_t n) const {
    return static_cast<std::size_t>(std::min<std::uint64_t>(n, file_size_ / 4 + 1));
  }

  std::string first_token() const { return tokens_.empty() ? "" : std::string(tokens_.front()); }

  [[noreturn]] void truncated(std::uint64_t vertices, std::uint64_t faces, std::uint64_t read_v,
                              std::uint64_t read_f) const {
    fail("truncated OFF data: the header announces " + std::to_string(vertices) + " vertices and " +
         std::to_string(faces) + " faces, the file ends after " + std::to_string(read_v) +
         " vertices and " + std::to_string(read_f) + " faces");
  }

  [[noreturn]] void out_of_range(std::uint64_t f, long long id, std::uint64_t vertices) const {
    fail(vertex_out_of_range("face " + std::to_string(f), std::to_string(id),
                             static_cast<std::size_t>(vertices)));
  }

  [[noreturn]] void fail_here(const std::string& problem) const {
    input_problem(path_, line_number_, problem);
  }
  [[noreturn]] void fail(const std::string& problem) const { input_problem(path_, problem); }

  const std::filesystem::path& path_;
  std::istream& in_;
  std::uintmax_t file_size_;
  std::string line_;
  std::vector<std::string_view> tokens_;  // of line_
  std::size_t used_ = 0;                  // tokens of the current line consumed by count()
  std::size_t line_number_ = 0;
};

}  // namespace

PolygonSoup read_off(const std::filesystem::path& path, std::istream& in,
                     std::uintmax_t file_size) {
  return OffReader(path, in, file_size).read();
}

}  // namespace cvtmesh
