// libFuzzer target: remesh on tiny meshes decoded from the bytes: at most 30 triangles over at
// most 24 vertices on a small integer grid (so that coplanar, collinear, coincident and
// cospherical configurations are common), and at most 50 seeds, random or given on the same
// grid. The input is repaired first, as the CLI does. InputError and InvalidArgument are
// answers; anything else is a finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/remesh.hpp"
#include "cvtmesh/repair.hpp"

namespace {

// Reads bytes in order; zeros once they run out.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return at_ < size_ ? data_[at_++] : 0; }
  double coordinate() { return static_cast<double>(static_cast<std::int8_t>(next())) / 8; }
  cvtmesh::Vec3 point() { return {coordinate(), coordinate(), coordinate()}; }

 private:
  const std::uint8_t* data_;
  std::size_t size_, at_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::uint8_t shape = in.next(), options = in.next();
  const std::size_t vertices = 3 + shape % 22, triangles = 1 + (shape / 22) % 30;
  cvtmesh::TriangleMesh mesh;
  for (std::size_t v = 0; v < vertices; ++v) mesh.vertices.push_back(in.point());
  for (std::size_t t = 0; t < triangles; ++t)
    mesh.triangles.push_back({static_cast<cvtmesh::Index>(in.next() % vertices),
                              static_cast<cvtmesh::Index>(in.next() % vertices),
                              static_cast<cvtmesh::Index>(in.next() % vertices)});
  cvtmesh::RemeshSettings s;
  s.vertices = 4 + in.next() % 47;
  s.iterations = options % 6;
  s.mode = static_cast<cvtmesh::CvtMode>((options / 6) % 3);
  s.features.sharp_edges = (options & 0x40) == 0;
  s.optimizer = (options & 0x80) ? cvtmesh::Optimizer::lloyd : cvtmesh::Optimizer::lbfgs;
  if (options % 5 == 0) {  // given seeds, distinct
    for (std::size_t k = 0; k < s.vertices; ++k) s.initial_seeds.push_back(in.point());
    std::sort(s.initial_seeds.begin(), s.initial_seeds.end());
    s.initial_seeds.erase(std::unique(s.initial_seeds.begin(), s.initial_seeds.end()),
                          s.initial_seeds.end());
    s.vertices = s.initial_seeds.size();
    if (s.vertices < 4) return 0;
  }
  s.hausdorff = cvtmesh::HausdorffSettings{.samples = 100};
  try {
    cvtmesh::repair_mesh(mesh);
    cvtmesh::remesh(mesh, s);
  } catch (const cvtmesh::InputError&) {
  } catch (const cvtmesh::InvalidArgument&) {
  }
  return 0;
}
