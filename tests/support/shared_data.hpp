// Where the shared test meshes live (../shared/data beside the repository, or the
// CVTMESH_SHARED_DATA environment variable). Tests and benchmarks that need them skip when the
// directory is absent.
#pragma once

#include <cstdlib>
#include <filesystem>

#include "cvtmesh/io.hpp"
#include "cvtmesh/repair.hpp"

namespace cvtmesh::testing {

inline std::filesystem::path shared_data() {
  if (const char* env = std::getenv("CVTMESH_SHARED_DATA")) return env;
  return CVTMESH_SHARED_DATA;
}

// A shared mesh, read and repaired as the command line does.
inline TriangleMesh shared_mesh(const char* name) {
  TriangleMesh mesh = read_mesh(shared_data() / name);
  repair_mesh(mesh);
  return mesh;
}

}  // namespace cvtmesh::testing
