#include <algorithm>
#include <cctype>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"

namespace cvtmesh {

std::optional<MeshFormat> format_from_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".off") return MeshFormat::off;
  if (ext == ".ply") return MeshFormat::ply;
  if (ext == ".stl") return MeshFormat::stl;
  return std::nullopt;
}

void ensure_distinct_output(const std::filesystem::path& input,
                            const std::filesystem::path& output) {
  std::error_code ec;
  const bool same = std::filesystem::exists(output, ec)
                        ? std::filesystem::equivalent(input, output, ec)
                        : std::filesystem::weakly_canonical(input, ec) ==
                              std::filesystem::weakly_canonical(output, ec);
  if (same) throw InvalidArgument(output.string() + ": refusing to write over the input mesh");
}

}  // namespace cvtmesh
