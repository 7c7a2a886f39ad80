// libFuzzer target: the seeds-file reader (`--seeds-file`, a text file of "x y z" lines) on any
// bytes. Seeds given as a mesh's vertices go through read_mesh, fuzzed on its own.
#include <cstddef>
#include <cstdint>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/sampling.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    cvtmesh::read_points(cvtmesh::fuzz::as_file(data, size, ".txt"));
  } catch (const cvtmesh::InputError&) {
  }
  return 0;
}
