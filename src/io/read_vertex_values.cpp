// Per-vertex values from a file: a sizing field (cvtmesh remesh --sizing).
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "cvtmesh/io.hpp"
#include "io/data_lines.hpp"
#include "io/input_problem.hpp"
#include "io/read_ply.hpp"

namespace cvtmesh {

std::vector<double> read_vertex_values(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) unreadable_file(path, "cannot open for reading");
  std::vector<double> values;
  if (format_from_extension(path) == MeshFormat::ply) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size == 0) input_problem(path, "file is empty");
    values = read_ply(path, in, size, true).vertex_scalar;
    for (std::size_t v = 0; v < values.size(); ++v)
      if (!std::isfinite(values[v]))
        input_problem(path, "vertex " + std::to_string(v) + ": the value is not finite");
  } else {
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
      std::istringstream words;
      if (!data_line(line, words)) continue;
      double value = 0;
      std::string extra;
      if (!(words >> value) || (words >> extra) || !std::isfinite(value))
        input_problem(path, number, "expected one finite number, got \"" + line + "\"");
      values.push_back(value);
    }
    if (in.bad()) input_problem(path, "read error");
  }
  if (values.empty()) input_problem(path, "no values");
  return values;
}

}  // namespace cvtmesh
