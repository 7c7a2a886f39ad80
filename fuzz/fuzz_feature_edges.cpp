// libFuzzer target: the feature-edge file reader (`remesh --feature-edges`) on any bytes.
#include <cstddef>
#include <cstdint>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/features.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    cvtmesh::read_feature_edges(cvtmesh::fuzz::as_file(data, size, ".edges"));
  } catch (const cvtmesh::InputError&) {
  }
  return 0;
}
