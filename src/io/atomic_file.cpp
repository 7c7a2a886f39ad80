#include "io/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include <fmt/core.h>

#include "cvtmesh/errors.hpp"

namespace cvtmesh::io {

namespace {

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  return path.parent_path() /
         fmt::format(".{}.tmp{}-{}", path.filename().string(), ::getpid(), counter++);
}

}  // namespace

void write_atomically(const std::filesystem::path& path, bool binary,
                      const std::function<bool(std::ostream&)>& write) {
  const std::filesystem::path tmp = temporary_path_for(path);
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw OutputError(path.string() + ": cannot write: " + why);
  };
  {
    std::ofstream out(tmp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
    if (!out) fail(std::strerror(errno));
    bool ok = false;
    try {
      ok = write(out);
    } catch (const std::exception& e) {
      fail(e.what());
    }
    out.flush();
    if (!ok || !out) fail("write failed (disk full or I/O error?)");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) fail(ec.message());
}

}  // namespace cvtmesh::io
