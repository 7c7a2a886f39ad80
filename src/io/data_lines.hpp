// Line-oriented text inputs (feature edges, sizing values): blank lines and lines whose first
// word starts with '#' carry no data.
#pragma once

#include <sstream>
#include <string>

namespace cvtmesh {

// Whether `line` carries data; if so, `fields` is set to read it from its start.
inline bool data_line(const std::string& line, std::istringstream& fields) {
  fields.clear();
  fields.str(line);
  std::string first;
  if (!(fields >> first) || first[0] == '#') return false;
  fields.clear();
  fields.seekg(0);
  return true;
}

}  // namespace cvtmesh
