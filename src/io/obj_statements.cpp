#include "io/obj_statements.hpp"

#include <sstream>

namespace cvtmesh {

namespace {

// The statement's keyword: its first word.
std::string keyword(const std::string& statement) {
  const auto begin = statement.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return {};
  const auto end = statement.find_first_of(" \t\r", begin);
  return statement.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// The statement's words joined by single spaces.
std::string single_spaced(const std::string& statement) {
  std::istringstream words(statement);
  std::string word, out;
  while (words >> word) {
    if (!out.empty()) out += ' ';
    out += word;
  }
  return out;
}

}  // namespace

std::string obj_for_cgal(std::istream& in) {
  std::string out, line, statement;
  const auto emit = [&] {
    const std::string k = keyword(statement);
    if (k == "l") return;
    // Spaces, single or not, CGAL's reader takes; other blanks between corners it does not.
    const bool blanks = statement.find_first_of("\t\v\f") != std::string::npos;
    out += k == "f" && blanks ? single_spaced(statement) : statement;
    out += '\n';
  };
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // A backslash ending the line joins the next one to it (not in a comment).
    const bool continued = !line.empty() && line.back() == '\\' && !keyword(line).starts_with('#');
    if (continued) line.back() = ' ';
    statement += line;
    if (continued) continue;
    emit();
    statement.clear();
  }
  if (!statement.empty()) emit();
  return out;
}

}  // namespace cvtmesh
