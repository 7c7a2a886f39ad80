#include "io/read_obj.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_problem.hpp"
#include "io/text_tokens.hpp"

namespace cvtmesh {

namespace {

// Statements of the format that say nothing about the surface's positions or faces: texture
// coordinates, normals, parameter-space vertices, polylines and points (a surface remesher
// ignores them), grouping, display and free-form attributes.
constexpr std::string_view kSkipped[] = {
    "vt",       "vn",       "vp",       "l",          "p",         "o",      "g",        "s",
    "mg",       "usemtl",   "mtllib",   "usemap",     "maplib",    "bevel",  "lod",      "ctech",
    "c_interp", "d_interp", "stech",    "shadow_obj", "trace_obj", "cstype", "deg",      "step",
    "bmat",     "con",      "curv",     "curv2",      "surf",      "parm",   "trim",     "hole",
    "scrv",     "sp",       "end",      "surf_1",     "q0_1",      "q1_1",   "curv2d_1", "surf_2",
    "q0_2",     "q1_2",     "curv2d_2", "bsp",        "bzp",       "cdc",    "cdp",      "res"};

class ObjReader {
 public:
  ObjReader(const std::filesystem::path& path, std::istream& in) : path_(path), in_(in) {}

  PolygonSoup read() {
    while (next_statement()) {
      const std::string_view keyword = words_.front();
      if (keyword == "v")
        vertex();
      else if (keyword == "f")
        face();
      else if (std::find(std::begin(kSkipped), std::end(kSkipped), keyword) == std::end(kSkipped))
        fail("unrecognized OBJ statement '" + printable(keyword) + "'");
    }
    if (in_.bad()) input_problem(path_, "read error");
    return std::move(soup_);
  }

 private:
  // The next statement with words, split into words_; false at the end. A comment runs from a
  // '#' to the end of its line; a line ending in a backslash goes on on the next.
  bool next_statement() {
    statement_.clear();
    while (std::getline(in_, line_)) {
      ++line_number_;
      if (statement_.empty()) first_line_ = line_number_;
      if (const std::size_t hash = line_.find('#'); hash != std::string::npos) line_.erase(hash);
      if (!line_.empty() && line_.back() == '\r') line_.pop_back();
      const bool continued = !line_.empty() && line_.back() == '\\';
      if (continued) line_.back() = ' ';
      statement_ += line_;
      if (continued) continue;
      split_words(statement_, words_);
      if (!words_.empty()) return true;
      statement_.clear();
    }
    split_words(statement_, words_);  // what a last line ending in a backslash began
    return !words_.empty();
  }

  void vertex() {
    if (words_.size() < 4)
      fail("vertex " + std::to_string(soup_.points.size()) + " has " +
           std::to_string(words_.size() - 1) + " coordinates (expected 3)");
    std::array<double, 3> p{};
    for (int k = 0; k < 3; ++k) {
      const std::optional<double> x = text_double(words_[k + 1]);
      if (!x)
        fail("vertex " + std::to_string(soup_.points.size()) + ": '" + printable(words_[k + 1]) +
             "' is not a number");
      p[k] = *x;
    }
    soup_.points.push_back(p);
  }

  // Corner ids from 1, or negative from the last vertex read so far (-1 is that one). An id that
  // reaches before the first vertex is kept wrapped around (the caller's check of ids shows it
  // signed), as is one past the last.
  void face() {
    for (std::size_t k = 1; k < words_.size(); ++k) {
      const std::string_view corner = words_[k];
      const std::optional<long long> id = text_integer(corner.substr(0, corner.find('/')));
      if (!id || *id == 0)
        fail("face " + std::to_string(soup_.polygon_count()) + ": corner '" + printable(corner) +
             "' is no vertex id" + (id ? " (they start at 1)" : ""));
      const long long count = static_cast<long long>(soup_.points.size());
      soup_.add_corner(static_cast<std::size_t>(*id >= 1 ? *id - 1 : count + *id));
    }
    soup_.end_polygon();
  }

  // A word as a message may show it: at most 40 characters, and not binary data.
  static std::string printable(std::string_view word) {
    const bool text = std::all_of(word.begin(), word.end(), [](char c) {
      return static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
    });
    if (!text) return "(binary data)";
    return word.size() <= 40 ? std::string(word) : std::string(word.substr(0, 40)) + "...";
  }

  [[noreturn]] void fail(const std::string& problem) const {
    input_problem(path_, first_line_, problem);
  }

  const std::filesystem::path& path_;
  std::istream& in_;
  std::string line_, statement_;
  std::vector<std::string_view> words_;  // of statement_
  std::size_t line_number_ = 0, first_line_ = 0;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup read_obj(const std::filesystem::path& path, std::istream& in) {
  return ObjReader(path, in).read();
}

}  // namespace cvtmesh
