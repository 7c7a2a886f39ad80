// The one-line messages of the readers: "FILE: problem", or "FILE:LINE: problem" where a line
// can be named, thrown as InputError.
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

}  // namespace cvtmesh
