// The one-line messages of the readers: "FILE: problem", or "FILE:LINE: problem" where a line
// can be named, thrown as InputError (FileError for a file that cannot be opened).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "cvtmesh/errors.hpp"

namespace cvtmesh {

[[noreturn]] inline void input_problem(const std::filesystem::path& path,
                                       const std::string& problem) {
  throw InputError(path.string() + ": " + problem);
}

[[noreturn]] inline void input_problem(const std::filesystem::path& path, std::size_t line,
                                       const std::string& problem) {
  throw InputError(path.string() + ":" + std::to_string(line) + ": " + problem);
}

// The problem of a face (`item`: "face 3", "triangle strip 0") that lists vertex `id` (as the file
// writes it) where the file has `vertices` vertices: one wording for every reader.
inline std::string vertex_out_of_range(const std::string& item, const std::string& id,
                                       std::size_t vertices) {
  return item + " references vertex " + id + ", out of range (the file has " +
         std::to_string(vertices) + " vertices)";
}

// A file that is missing or cannot be opened, thrown as FileError.
[[noreturn]] inline void unreadable_file(const std::filesystem::path& path,
                                         const std::string& problem) {
  throw FileError(path.string() + ": " + problem);
}

}  // namespace cvtmesh
