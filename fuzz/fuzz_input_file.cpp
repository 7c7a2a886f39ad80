#include "fuzz_input_file.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace cvtmesh::fuzz {

std::filesystem::path as_file(const std::uint8_t* data, std::size_t size, const char* extension) {
  static const std::filesystem::path folder = std::filesystem::is_directory("/dev/shm")
                                                  ? "/dev/shm"
                                                  : std::filesystem::temp_directory_path();
  const std::filesystem::path path =
      folder / ("cvtmesh-fuzz-" + std::to_string(getpid()) + extension);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) std::abort();  // the fuzzer's own failure, not the reader's
  return path;
}

}  // namespace cvtmesh::fuzz
