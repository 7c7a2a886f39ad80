// The PLY reader: elements and properties it must read past, both byte orders, and a clear error
// for each malformed header or count (CGAL's reader crashed on some of them under fuzzing).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "support/temp_dir.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TriangleMesh read_text(const TempDir& dir, const std::string& text) {
  write_file(dir / "m.ply", text);
  return read_mesh(dir / "m.ply");
}

std::string error_of(const TempDir& dir, const std::string& text) {
  write_file(dir / "m.ply", text);
  return read_mesh_error(dir / "m.ply");
}

TEST(ReadPly, ReadsPastOtherElementsAndProperties) {
  TempDir dir;
  const TriangleMesh m =
      read_text(dir,
                "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nelement material 1\r\n"
                "property list uchar float weights\r\nproperty uchar id\r\nelement vertex 3\r\n"
                "property double nx\r\nproperty double z\r\nproperty int y\r\nproperty double x\r\n"
                "property uchar red\r\nelement face 1\r\nproperty uchar flags\r\n"
                "property list int uint vertex_index\r\nproperty list uchar float texcoord\r\n"
                "end_header\r\n2 0.5 1.5 7\r\n9 0 0 0 255\r\n9 0.25 0 1 0\r\n9 0 1 0 0\r\n"
                "1 3 0 1 2 6 0 0 1 0 0 1\r\n");
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[1], (Vec3{1, 0, 0.25}));
  EXPECT_EQ(m.vertices[2], (Vec3{0, 1, 0}));
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
}

TEST(ReadPly, BinaryLittleEndianWithWideListCounts) {
  TempDir dir;
  std::string body;
  auto put = [&body](const auto& value) {
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    if constexpr (std::endian::native == std::endian::big)
      std::reverse(bytes, bytes + sizeof value);
    body.append(bytes, sizeof value);
  };
  for (double c : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 2.5, 0.0}) put(c);
  put(std::uint32_t{3});
  for (std::uint16_t v : {0, 1, 2}) put(v);
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float64 x\n"
      "property float64 y\nproperty float64 z\nelement face 1\n"
      "property list uint32 uint16 vertex_indices\nend_header\n";
  const TriangleMesh m = read_text(dir, header + body);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.vertices[2], (Vec3{0, 2.5, 0}));
  // A corrupt list count of 2^32 - 1 fails on the bytes it would need, allocating nothing.
  std::string corrupt = header + body;
  std::memset(corrupt.data() + header.size() + 72, 0xFF, 4);
  EXPECT_NE(error_of(dir, corrupt).find("announces a list of 4294967295 entries"),
            std::string::npos);
  EXPECT_NE(error_of(dir, header + body.substr(0, 40)).find("truncated PLY data"),
            std::string::npos);
}

TEST(ReadPly, EachHeaderOrDataProblemIsNamed) {
  TempDir dir;
  const std::string path = (dir / "m.ply").string();
  const std::string start = "ply\nformat ascii 1.0\n";
  const std::string vertex =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string data = "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  struct Case {
    std::string text, message;
  };
  for (const Case& c : {
           Case{"PLY\n", ":1: not a PLY file"},
           Case{start + vertex + face, "no end_header line"},
           Case{"ply\n" + vertex + face + data, "no format line"},
           Case{"ply\nformat binary 1.0\n", ":2: unknown PLY format 'binary'"},
           Case{start + "property float x\n" + vertex,
                ":3: malformed PLY header: a property before"},
           Case{start + "elntme eface 4\n", ":3: malformed PLY header: unknown keyword 'elntme'"},
           Case{start + "element vertex -3\n", ":3: malformed PLY header: expected 'element"},
           Case{start + vertex + "property float x\n", "property 'x' twice in element 'vertex'"},
           Case{start + vertex + "property vec3 n\n", "unknown PLY property type 'vec3'"},
           Case{start + vertex + face + "property list float int i\n", "list count type 'float'"},
           Case{start +
                    "element vertex 1\nproperty list uchar float x\nproperty float y\n"
                    "property float z\n" +
                    face + data,
                "no scalar property 'x'"},
           // The fuzzing finding: a NUL in a property name, a list named like a coordinate.
           Case{start + "element vertex 3\nproperty float x" + std::string(3, '\0') + "\n",
                ":4: malformed PLY header: control characters"},
           Case{
               start + vertex + "element face 1\nproperty list uchar float vertex_indices\n" + data,
               "no integer list 'vertex_indices'"},
           Case{start + vertex + face + "end_header\n0 0 0\n1 zero 0\n",
                ":11: PLY element vertex "
                "item 1: 'zero' is not a number"},
           Case{start + vertex + face + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n",
                ":13: PLY element face item 0: '1.5' is not an integer"},
           Case{start + vertex + face + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
                "face 0 references vertex -1, out of range (the file has 3 vertices)"},
           Case{start + vertex + face + "end_header\n0 0 0\n1 0 0\n0 1 0\n",
                "truncated PLY data: the file ends in element face, item 0 of 1"},
           Case{start + vertex + face + "end_header\n0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n",
                ":13: truncated PLY data: element face item 0 announces a list of 200 entries"},
       }) {
    const std::string what = error_of(dir, c.text);
    EXPECT_EQ(what.rfind(path, 0), 0u) << what;
    EXPECT_NE(what.find(c.message), std::string::npos) << what << "\nexpected: " << c.message;
  }
}

TEST(ReadPly, AnElementWithoutPropertiesTakesNoData) {
  TempDir dir;
  const TriangleMesh m = read_text(
      dir,
      "ply\nformat ascii 1.0\nelement marker 7535956297025342\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(m.triangles.size(), 1u);
}

// Triangle strips (element tristrips, as MeshLab's and the Stanford repository's files write
// them): abc, cbd, cde... all in the first triangle's orientation; -1 starts a new strip; the
// triangles with a vertex twice that join strips into one list are no triangles. Strips written
// apart and joined give the same triangles, here all facing -z, beside the faces of a face element.
TEST(ReadPly, TriangleStripsBecomeTrianglesOfOneOrientation) {
  TempDir dir;
  const std::string points = "0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n2 1 0\n";
  // A file of the 6 points above, with `elements` (header lines) holding `data`.
  const auto ply = [&](const std::string& elements, const std::string& data) {
    return "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
           "property float z\n" +
           elements + "end_header\n" + points + data;
  };
  const std::string strips_of = "element tristrips 1\nproperty list int int vertex_indices\n";
  const std::vector<Triangle> expected{{0, 1, 2}, {2, 1, 3}, {2, 3, 4}, {4, 3, 5}};
  for (const std::string& strips : {std::string("9 0 1 2 3 -1 2 3 4 5"),       // two strips
                                    std::string("10 0 1 2 3 3 2 2 3 4 5")}) {  // joined
    const TriangleMesh m = read_text(dir, ply(strips_of, strips + "\n"));
    EXPECT_EQ(m.triangles, expected) << strips;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto [a, b, c] = m.corners(t);
      EXPECT_LT(cross(b - a, c - a).z, 0) << strips << ", triangle " << t;
    }
  }
  const TriangleMesh both =
      read_text(dir, ply("element face 1\nproperty list uchar int vertex_indices\n" + strips_of,
                         "3 0 2 4\n4 0 1 2 3\n"));
  EXPECT_EQ(both.triangles, (std::vector<Triangle>{{0, 2, 4}, {0, 1, 2}, {2, 1, 3}}));
  EXPECT_NE(error_of(dir, ply(strips_of, "4 0 1 2 9\n"))
                .find("triangle strip 0 references vertex 9, out of range"),
            std::string::npos);
  EXPECT_NE(error_of(dir, ply("element tristrips 1\nproperty list int float vertex_indices\n",
                              "3 0 1 2\n"))
                .find("PLY element tristrips has no integer list"),
            std::string::npos);
}

TEST(ReadPly, MissingElementsLeaveAnEmptyMesh) {
  TempDir dir;
  EXPECT_NE(error_of(dir,
                     "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                     "property float y\nproperty float z\nend_header\n0 0 0\n")
                .find("empty mesh: no faces"),
            std::string::npos);
}

}  // namespace
}  // namespace cvtmesh
