// A scratch folder for a test, removed with everything in it when the test ends.
#pragma once

#include <filesystem>
#include <string>

namespace cvtmesh::testing {

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

void write_file(const std::filesystem::path& path, const std::string& bytes);
std::string read_file(const std::filesystem::path& path);

// The message of the InputError that reading `path` as a mesh throws, or "no error".
std::string read_mesh_error(const std::filesystem::path& path);

}  // namespace cvtmesh::testing
