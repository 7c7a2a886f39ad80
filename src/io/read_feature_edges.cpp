// The user's feature-edge list: "a b" per line, vertex ids of the input mesh.
#include <fstream>
#include <sstream>
#include <string>

#include "cvtmesh/features.hpp"
#include "io/data_lines.hpp"
#include "io/input_problem.hpp"

namespace cvtmesh {

std::vector<Edge> read_feature_edges(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) unreadable_file(path, "cannot open the feature-edge file");
  std::vector<Edge> edges;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream fields;
    if (!data_line(line, fields)) continue;
    long long a = -1, b = -1;
    std::string rest;
    if (!(fields >> a >> b) || (fields >> rest) || a < 0 || b < 0 || a > 0xFFFFFFFELL ||
        b > 0xFFFFFFFELL || a == b)
      input_problem(path, number, "expected two different vertex ids, got \"" + line + "\"");
    edges.push_back({static_cast<Index>(a), static_cast<Index>(b)});
  }
  if (in.bad()) input_problem(path, "read error");
  return edges;
}

}  // namespace cvtmesh
