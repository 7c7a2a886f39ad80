// libFuzzer target: read_mesh on any bytes, as a file of the format CVTMESH_FUZZ_EXTENSION names
// (one binary per format), then the repair and topology analysis every command runs next. A
// clean InputError is the expected answer to garbage; anything else (a crash, a sanitizer
// report, another exception) is a finding.
#include <cstddef>
#include <cstdint>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "cvtmesh/repair.hpp"
#include "cvtmesh/topology.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = cvtmesh::fuzz::as_file(data, size, CVTMESH_FUZZ_EXTENSION);
  try {
    cvtmesh::TriangleMesh mesh = cvtmesh::read_mesh(path);
    cvtmesh::repair_mesh(mesh);
    cvtmesh::analyze_topology(mesh);
  } catch (const cvtmesh::InputError&) {
  }
  return 0;
}
