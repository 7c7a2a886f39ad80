// Writing a file so that it appears whole or not at all.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace cvtmesh::io {

// Calls `write` on a stream to a temporary file beside `path`, then renames it to `path`.
// On any failure the temporary file is removed, `path` is untouched, and OutputError is thrown.
// `write` returns false (or throws) to signal failure.
void write_atomically(const std::filesystem::path& path, bool binary,
                      const std::function<bool(std::ostream&)>& write);

}  // namespace cvtmesh::io
