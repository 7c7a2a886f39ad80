// PLY as Paul Bourke's specification defines it: a text header of elements, each with a count
// and typed properties (scalars or lists), then the elements' data in order, as text or as
// binary of either byte order. The data are read from memory, where every count can be checked
// against the bytes that are left. Faces come from a "face" element, triangle strips from a
// "tristrips" element (as MeshLab's and the Stanford repository's files write them), or both.
#include "io/read_ply.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "io/input_problem.hpp"
#include "io/text_tokens.hpp"

namespace cvtmesh {

namespace {

enum class Type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::optional<Type> type_named(std::string_view name) {
  static constexpr std::pair<std::string_view, Type> kNames[] = {
      {"char", Type::int8},      {"int8", Type::int8},       {"uchar", Type::uint8},
      {"uint8", Type::uint8},    {"short", Type::int16},     {"int16", Type::int16},
      {"ushort", Type::uint16},  {"uint16", Type::uint16},   {"int", Type::int32},
      {"int32", Type::int32},    {"uint", Type::uint32},     {"uint32", Type::uint32},
      {"float", Type::float32},  {"float32", Type::float32}, {"double", Type::float64},
      {"float64", Type::float64}};
  for (const auto& [n, t] : kNames)
    if (n == name) return t;
  return std::nullopt;
}

std::size_t size_of(Type type) {
  switch (type) {
    case Type::int8:
    case Type::uint8:
      return 1;
    case Type::int16:
    case Type::uint16:
      return 2;
    case Type::int32:
    case Type::uint32:
    case Type::float32:
      return 4;
    case Type::float64:
      return 8;
  }
  return 0;
}

struct Property {
  std::string name;
  bool list = false;
  Type count_type = Type::uint8;  // lists only
  Type type = Type::float32;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Format { ascii, binary_little_endian, binary_big_endian };

class PlyReader {
 public:
  PlyReader(const std::filesystem::path& path, std::istream& in, std::uintmax_t file_size,
            bool with_scalar)
      : path_(path), in_(in), file_size_(file_size), with_scalar_(with_scalar) {}

  PolygonSoup read() {
    read_header();
    read_data();
    if (in_.bad()) fail("read error");
    ++line_number_;  // the data's first line
    for (const Element& element : elements_) read_element(element);
    return std::move(soup_);
  }

 private:
  // Everything after the header into data_: in one read of what the file's size says is left
  // (a character at a time, with the string growing, was a third of reading a 270k-triangle
  // file), then whatever follows, should the file have grown.
  void read_data() {
    const std::streamoff header = in_.tellg();
    const std::uintmax_t left = header >= 0 && static_cast<std::uintmax_t>(header) < file_size_
                                    ? file_size_ - static_cast<std::uintmax_t>(header)
                                    : 0;
    data_.resize(static_cast<std::size_t>(left));
    in_.read(data_.data(), static_cast<std::streamsize>(left));
    data_.resize(static_cast<std::size_t>(in_.gcount()));
    if (in_.good())
      data_.append(std::istreambuf_iterator<char>(in_), std::istreambuf_iterator<char>());
  }

  void read_header() {
    std::string line;
    bool format_seen = false;
    for (;;) {
      if (!std::getline(in_, line)) fail("malformed PLY header: no end_header line");
      ++line_number_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line_number_ == 1) {
        if (line != "ply") fail_here("not a PLY file: the first line is not 'ply'");
        continue;
      }
      if (std::any_of(line.begin(), line.end(),
                      [](char c) { return static_cast<unsigned char>(c) < 32 && c != '\t'; }))
        fail_here("malformed PLY header: control characters in a header line");
      std::istringstream stream(line);
      std::vector<std::string> words{std::istream_iterator<std::string>(stream), {}};
      if (words.empty()) continue;
      const std::string& keyword = words[0];
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "end_header") break;
      if (keyword == "format") {
        format_ = parse_format(words);
        format_seen = true;
      } else if (keyword == "element") {
        add_element(words);
      } else if (keyword == "property") {
        add_property(words);
      } else {
        fail_here("malformed PLY header: unknown keyword '" + keyword + "'");
      }
    }
    if (!format_seen) fail("malformed PLY header: no format line");
    find_roles();
  }

  Format parse_format(const std::vector<std::string>& words) const {
    if (words.size() != 3 || words[2] != "1.0")
      fail_here("malformed PLY header: expected 'format <type> 1.0'");
    if (words[1] == "ascii") return Format::ascii;
    if (words[1] == "binary_little_endian") return Format::binary_little_endian;
    if (words[1] == "binary_big_endian") return Format::binary_big_endian;
    fail_here("unknown PLY format '" + words[1] + "'");
  }

  void add_element(const std::vector<std::string>& words) {
    const std::optional<std::uint64_t> count =
        words.size() == 3 ? text_count(words[2]) : std::nullopt;
    if (!count) fail_here("malformed PLY header: expected 'element <name> <count>'");
    for (const Element& e : elements_)
      if (e.name == words[1]) fail_here("malformed PLY header: element '" + e.name + "' twice");
    elements_.push_back({words[1], *count, {}});
  }

  void add_property(const std::vector<std::string>& words) {
    if (elements_.empty()) fail_here("malformed PLY header: a property before any element");
    Property property;
    const bool list = words.size() == 5 && words[1] == "list";
    if (!list && words.size() != 3)
      fail_here(
          "malformed PLY header: expected 'property <type> <name>' or "
          "'property list <count type> <type> <name>'");
    property.list = list;
    property.name = words.back();
    const auto type = type_named(words[list ? 3 : 1]);
    if (!type) fail_here("unknown PLY property type '" + words[list ? 3 : 1] + "'");
    property.type = *type;
    if (list) {
      const auto count_type = type_named(words[2]);
      if (!count_type || *count_type == Type::float32 || *count_type == Type::float64)
        fail_here("PLY list count type '" + words[2] + "' is not an integer type");
      property.count_type = *count_type;
    }
    Element& element = elements_.back();
    for (const Property& p : element.properties)
      if (p.name == property.name)
        fail_here("malformed PLY header: property '" + p.name + "' twice in element '" +
                  element.name + "'");
    element.properties.push_back(property);
  }

  // Which element and properties hold the positions and the faces.
  void find_roles() {
    for (std::size_t e = 0; e < elements_.size(); ++e) {
      const Element& element = elements_[e];
      if (element.name == "vertex") {
        vertex_element_ = e;
        vertex_count_ = element.count;
        for (int axis = 0; axis < 3; ++axis) {
          const std::string name(1, static_cast<char>('x' + axis));
          const auto p = find_property(element, name);
          if (!p || element.properties[*p].list)
            fail("PLY element vertex has no scalar property '" + name + "'");
          coordinate_[axis] = *p;
        }
        if (with_scalar_) find_scalar(element);
      } else if (element.name == "face") {
        face_element_ = e;
        indices_ = index_list(element);
      } else if (element.name == "tristrips") {
        strip_element_ = e;
        strip_indices_ = index_list(element);
      }
    }
  }

  // The integer list of vertex ids of a face or tristrips element.
  std::size_t index_list(const Element& element) const {
    auto p = find_property(element, "vertex_indices");
    if (!p) p = find_property(element, "vertex_index");
    if (!p || !element.properties[*p].list || element.properties[*p].type == Type::float32 ||
        element.properties[*p].type == Type::float64)
      fail("PLY element " + element.name +
           " has no integer list 'vertex_indices' or 'vertex_index'");
    return *p;
  }

  // The vertex scalar asked for: the first that is no position, normal or colour.
  void find_scalar(const Element& element) {
    static constexpr std::string_view kKnown[] = {"x",  "y",   "z",     "nx",   "ny",
                                                  "nz", "red", "green", "blue", "alpha"};
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const Property& property = element.properties[p];
      if (!property.list &&
          std::find(std::begin(kKnown), std::end(kKnown), property.name) == std::end(kKnown)) {
        scalar_ = p;
        return;
      }
    }
    fail("PLY element vertex has no scalar property besides positions, normals and colours");
  }

  static std::optional<std::size_t> find_property(const Element& element, std::string_view name) {
    for (std::size_t p = 0; p < element.properties.size(); ++p)
      if (element.properties[p].name == name) return p;
    return std::nullopt;
  }

  void read_element(const Element& element) {
    const std::size_t e = static_cast<std::size_t>(&element - elements_.data());
    const bool vertices = vertex_element_ && *vertex_element_ == e;
    const bool faces = face_element_ && *face_element_ == e;
    const bool strips = strip_element_ && *strip_element_ == e;
    // Items without properties take no bytes, however many the header announces (found by
    // fuzzing: 7.5e15 of them kept the loop below going for hours).
    if (element.properties.empty()) return;
    if (vertices) soup_.points.reserve(capped(element.count));
    if (faces) soup_.reserve_polygons(capped(element.count));
    for (std::uint64_t item = 0; item < element.count; ++item) {
      std::array<double, 3> point{};
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        if (!property.list) {
          const double value = scalar(property.type, element, item);
          for (int axis = 0; axis < 3; ++axis)
            if (vertices && coordinate_[axis] == p) point[axis] = value;
          if (vertices && scalar_ == p) soup_.vertex_scalar.push_back(value);
          continue;
        }
        const std::uint64_t count = list_count(property, element, item);
        const bool keep = (faces && p == indices_) || (strips && p == strip_indices_);
        ids_.clear();
        for (std::uint64_t k = 0; k < count; ++k) {
          const double value = scalar(property.type, element, item);
          if (keep) ids_.push_back(value);
        }
        if (!keep) continue;
        if (strips) {
          add_strips(ids_, item);
          continue;
        }
        for (const double value : ids_) soup_.add_corner(vertex_id(value, "face", item));
        soup_.end_polygon();
      }
      if (vertices) soup_.points.push_back(point);
    }
  }

  std::uint64_t list_count(const Property& property, const Element& element, std::uint64_t item) {
    const double value = scalar(property.count_type, element, item);
    // Each entry takes at least its size in binary, at least 2 bytes ("0 ") as text.
    const std::size_t least = format_ == Format::ascii ? 2 : size_of(property.type);
    if (value < 0 || static_cast<double>(data_.size() - at_) / static_cast<double>(least) < value)
      fail_at("truncated PLY data: element " + element.name + " item " + std::to_string(item) +
              " announces a list of " + number_text(value) + " entries, more than the file holds");
    return static_cast<std::uint64_t>(value);
  }

  // `what` `item`: the face or triangle strip that lists the id, for the error.
  std::size_t vertex_id(double value, const char* what, std::uint64_t item) const {
    if (!(value >= 0 && value < static_cast<double>(vertex_count_)))
      fail(vertex_out_of_range(std::string(what) + " " + std::to_string(item), number_text(value),
                               vertex_count_));
    return static_cast<std::size_t>(value);
  }

  // The triangles of the strips that `ids` lists (item `item` of the tristrips element, as the
  // Stanford and VCG/MeshLab PLY files write them): vertices a, b, c, d, e... make triangles abc,
  // cbd, cde..., every second one turned so that all take the first's orientation; -1 starts a
  // new strip. A triangle with a vertex twice is how writers join strips into one list, no part
  // of the surface, and is skipped (it keeps its place in the alternation).
  void add_strips(const std::vector<double>& ids, std::uint64_t item) {
    std::vector<std::size_t> strip;
    for (const double value : ids) {
      if (value == -1) {
        strip.clear();
        continue;
      }
      strip.push_back(vertex_id(value, "triangle strip", item));
      const std::size_t n = strip.size();
      if (n < 3) continue;
      const std::size_t a = strip[n - 3], b = strip[n - 2], c = strip[n - 1];
      if (a == b || b == c || c == a) continue;
      if (n % 2 == 1)
        soup_.add_polygon({a, b, c});
      else
        soup_.add_polygon({b, a, c});
    }
  }

  double scalar(Type type, const Element& element, std::uint64_t item) {
    return format_ == Format::ascii ? text_scalar(type, element, item)
                                    : binary_scalar(type, element, item);
  }

  double text_scalar(Type type, const Element& element, std::uint64_t item) {
    while (at_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[at_]))) {
      if (data_[at_] == '\n') ++line_number_;
      ++at_;
    }
    if (at_ == data_.size()) truncated(element, item);
    std::size_t end = at_;
    while (end < data_.size() && !std::isspace(static_cast<unsigned char>(data_[end]))) ++end;
    std::string_view token(data_.data() + at_, end - at_);
    at_ = end;
    // A huge magnitude reads as infinite, refused later.
    const std::optional<double> value = text_double(token);
    const bool integer = type != Type::float32 && type != Type::float64;
    if (!value || (integer && *value != std::floor(*value)))
      fail_here("PLY element " + element.name + " item " + std::to_string(item) + ": '" +
                std::string(token) + "' is not " + (integer ? "an integer" : "a number"));
    return *value;
  }

  double binary_scalar(Type type, const Element& element, std::uint64_t item) {
    const std::size_t n = size_of(type);
    if (data_.size() - at_ < n) truncated(element, item);
    unsigned char bytes[8];
    std::memcpy(bytes, data_.data() + at_, n);
    at_ += n;
    if ((format_ == Format::binary_big_endian) != (std::endian::native == std::endian::big))
      std::reverse(bytes, bytes + n);
    auto as = [&bytes]<typename T>(T) {
      T value;
      std::memcpy(&value, bytes, sizeof value);
      return static_cast<double>(value);
    };
    switch (type) {
      case Type::int8:
        return as(std::int8_t{});
      case Type::uint8:
        return as(std::uint8_t{});
      case Type::int16:
        return as(std::int16_t{});
      case Type::uint16:
        return as(std::uint16_t{});
      case Type::int32:
        return as(std::int32_t{});
      case Type::uint32:
        return as(std::uint32_t{});
      case Type::float32:
        return as(float{});
      case Type::float64:
        return as(double{});
    }
    return 0;
  }

  static std::string number_text(double value) {
    std::ostringstream s;
    s.precision(17);
    s << value;
    return s.str();
  }

  // A count from the header reserves no more than the file could hold.
  std::size_t capped(std::uint64_t n) const {
    return static_cast<std::size_t>(std::min<std::uint64_t>(n, file_size_ / 2 + 1));
  }

  [[noreturn]] void truncated(const Element& element, std::uint64_t item) const {
    fail("truncated PLY data: the file ends in element " + element.name + ", item " +
         std::to_string(item) + " of " + std::to_string(element.count));
  }

  // Text data name their line; binary data have none.
  [[noreturn]] void fail_at(const std::string& problem) const {
    if (format_ == Format::ascii) fail_here(problem);
    fail(problem);
  }

  [[noreturn]] void fail_here(const std::string& problem) const {
    input_problem(path_, line_number_, problem);
  }
  [[noreturn]] void fail(const std::string& problem) const { input_problem(path_, problem); }

  const std::filesystem::path& path_;
  std::istream& in_;
  std::uintmax_t file_size_;
  Format format_ = Format::ascii;
  std::vector<Element> elements_;
  std::optional<std::size_t> vertex_element_, face_element_, strip_element_;
  std::uint64_t vertex_count_ = 0;
  std::size_t coordinate_[3] = {0, 0, 0};
  std::size_t indices_ = 0, strip_indices_ = 0;  // the id lists of faces and triangle strips
  std::vector<double> ids_;                      // the current face's or strip's ids, as read
  bool with_scalar_;
  std::optional<std::size_t> scalar_;  // the vertex scalar's property, when asked for
  std::string data_;                   // everything after the header
  std::size_t at_ = 0;
  std::size_t line_number_ = 0;
  PolygonSoup soup_;
};

}  // namespace

PolygonSoup read_ply(const std::filesystem::path& path, std::istream& in, std::uintmax_t file_size,
                     bool with_scalar) {
  return PlyReader(path, in, file_size, with_scalar).read();
}

}  // namespace cvtmesh
