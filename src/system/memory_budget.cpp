#include "system/memory_budget.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cvtmesh/errors.hpp"

namespace cvtmesh {

namespace {

// bench/scale.py, peak resident memory of `cvtmesh remesh` (reading the input included): a
// 2M-triangle torus to 100k vertices 1,272 MB, igea (269k triangles) to 500k 784 MB, one
// triangle to 100k 208 MB, 10,000 icosahedra (200k triangles) to 120k 268 MB. A fit gives about
// 560 bytes per triangle, 1,120 per seed and 100 MB; rounded up, so that the check refuses only
// what would not fit. With the record that lets each extraction replay the last
// (TraversalMemory), the torus peaks at 1,465 MB and igea at 973 MB (1,431 and 814 just before
// it): 1,300 bytes per seed became 1,500.
constexpr std::uint64_t kBytesPerTriangle = 650;
constexpr std::uint64_t kBytesPerSeed = 1500;
constexpr std::uint64_t kBaseBytes = 110ull << 20;  // libraries, thread pools, buffers

// A "Key: value kB" line of a /proc file, in bytes.
std::optional<std::uint64_t> proc_field(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + ":", 0) == 0) {
      std::istringstream words(line.substr(key.size() + 1));
      std::uint64_t kb = 0;
      if (words >> kb) return kb * 1024;
    }
  return std::nullopt;
}

std::optional<std::uint64_t> file_number(const char* file) {
  std::ifstream in(file);
  std::uint64_t value = 0;
  if (in >> value) return value;  // "max" (no limit) does not parse
  return std::nullopt;
}

std::string gib(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1ull << 30));
  return text;
}

}  // namespace

std::uint64_t estimated_peak_bytes(std::size_t triangles, std::size_t seeds) {
  return kBaseBytes + kBytesPerTriangle * triangles + kBytesPerSeed * seeds;
}

std::optional<std::uint64_t> available_memory_bytes() {
  std::optional<std::uint64_t> least = proc_field("/proc/meminfo", "MemAvailable");
  const auto lower = [&](std::uint64_t v) { least = least ? std::min(*least, v) : v; };
  const auto limit = file_number("/sys/fs/cgroup/memory.max");
  const auto usage = file_number("/sys/fs/cgroup/memory.current");
  if (limit && usage) lower(*limit > *usage ? *limit - *usage : 0);
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t size = proc_field("/proc/self/status", "VmSize").value_or(0);
    lower(as.rlim_cur > size ? as.rlim_cur - size : 0);
  }
  return least;
}

void check_memory_for(std::size_t triangles, std::size_t seeds) {
  const std::uint64_t needed = estimated_peak_bytes(triangles, seeds);
  const std::optional<std::uint64_t> available = available_memory_bytes();
  if (available && needed > *available)
    throw ResourceError("remeshing " + std::to_string(triangles) + " triangles to " +
                        std::to_string(seeds) + " vertices needs about " + gib(needed) +
                        " of memory; " + gib(*available) + " are available");
}

}  // namespace cvtmesh
