// Points on a surface: random area-uniform samples, and seed files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

// `count` points uniformly distributed by area on the surface; the same (mesh, count, seed)
// gives the same points on any thread count. Throws InvalidArgument if the surface has no area.
std::vector<Vec3> sample_surface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed);

// Reads points: a mesh file's vertices (by extension .obj/.off/.ply/.stl), or else a text file
// with one "x y z" per line (blank lines and lines starting with # are skipped). Throws
// InputError naming the file, and the line for text files.
std::vector<Vec3> read_points(const std::filesystem::path& path);

}  // namespace cvtmesh
