// The OFF reader: the header variants Geomview defines, binary OFF, and a line-numbered error
// for each way a file can be malformed (CGAL's scanner read out of bounds on some of them).
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/io.hpp"
#include "support/temp_dir.hpp"

namespace cvtmesh {
namespace {

using namespace cvtmesh::testing;

TriangleMesh read_text(const TempDir& dir, const std::string& text) {
  write_file(dir / "m.off", text);
  return read_mesh(dir / "m.off");
}

std::string error_of(const TempDir& dir, const std::string& text) {
  write_file(dir / "m.off", text);
  return read_mesh_error(dir / "m.off");
}

TEST(ReadOff, SkipsColoursNormalsAndTexturesOfAnyWidth) {
  TempDir dir;
  // Vertex colours as an index, RGB and RGBA, face colours, comments, blank lines.
  const TriangleMesh m = read_text(dir,
                                   "COFF # coloured\n\n3 1 0\n0 0 0 7\n1 0 0 255 0 0\n"
                                   "0 1 0 0 0 1 0.5 # rgba\n3 0 1 2 1 0 0\n");
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[1], (Vec3{1, 0, 0}));
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(read_text(dir,
                      "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 1 1 0 0\n1 0 0 0 0 1 1 1 1 1 0\n"
                      "0 1 0 0 0 1 1 1 1 0 1\n3 0 1 2\n")
                .vertices[2],
            (Vec3{0, 1, 0}));
}

TEST(ReadOff, CountsOnTheKeywordLineHeaderlessHomogeneousAndDimension) {
  TempDir dir;
  EXPECT_EQ(read_text(dir, "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").triangles.size(), 1u);
  EXPECT_EQ(read_text(dir, "3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").vertices.size(), 3u);
  EXPECT_EQ(read_text(dir, "4OFF\n3 1 0\n0 0 0 1\n2 0 0 2\n0 4 0 4\n3 0 1 2\n").vertices[1],
            (Vec3{1, 0, 0}));
  EXPECT_EQ(read_text(dir, "nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").vertices.size(), 3u);
  EXPECT_NE(error_of(dir, "nOFF\n2\n3 1 0\n0 0\n1 0\n0 1\n3 0 1 2\n").find("dimension 2"),
            std::string::npos);
}

void put_word(std::string& bytes, std::uint32_t w) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes += static_cast<char>((w >> shift) & 0xFF);
}

void put_float(std::string& bytes, float f) {
  put_word(bytes, std::bit_cast<std::uint32_t>(f));
}

TEST(ReadOff, BinaryOff) {
  TempDir dir;
  std::string file = "OFF BINARY\n";
  for (std::uint32_t count : {4u, 2u, 0u}) put_word(file, count);
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.5f, 0.f}) put_float(file, c);
  for (std::uint32_t w : {3u, 0u, 1u, 2u, 0u, 3u, 0u, 2u, 3u, 3u})
    put_word(file, w);  // face 2 carries an RGB colour
  for (float c : {1.f, 0.f, 0.f}) put_float(file, c);
  const TriangleMesh m = read_text(dir, file);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.vertices[3], (Vec3{0, 1.5, 0}));
  EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
  file.resize(file.size() - 5);
  EXPECT_NE(error_of(dir, file).find("truncated binary OFF"), std::string::npos);
}

// pmp-library writes binary OFF without a colour count after each face's indices, in big-endian
// words since its version 3 and in little-endian ones before (its own data folder's files).
TEST(ReadOff, BinaryOffAsPmpLibraryWritesIt) {
  TempDir dir;
  for (const bool little_endian : {false, true}) {
    const auto word = [&](std::string& bytes, std::uint32_t w) {
      for (int k = 0; k < 4; ++k)
        bytes += static_cast<char>((w >> (little_endian ? 8 * k : 24 - 8 * k)) & 0xFF);
    };
    std::string file = "OFF BINARY\n";
    for (std::uint32_t count : {4u, 2u, 0u}) word(file, count);
    for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.5f, 0.f})
      word(file, std::bit_cast<std::uint32_t>(c));
    for (std::uint32_t w : {3u, 0u, 1u, 2u, 3u, 0u, 2u, 3u}) word(file, w);
    const TriangleMesh m = read_text(dir, file);
    ASSERT_EQ(m.triangles.size(), 2u) << "little-endian " << little_endian;
    EXPECT_EQ(m.vertices[3], (Vec3{0, 1.5, 0}));
    EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
    // Cut short, it is no layout's: the error is the one Geomview's layout found.
    file.resize(file.size() - 5);
    EXPECT_NE(error_of(dir, file).find("binary OFF"), std::string::npos);
  }
}

TEST(ReadOff, EachProblemIsNamedWithItsLine) {
  TempDir dir;
  const std::string path = (dir / "m.off").string();
  struct Case {
    std::string text, message;
  };
  for (const Case& c : {
           // A coloured vertex line too short for its coordinates (the fuzzing finding).
           Case{"COFF\n3 1 0\n0 OFF\n1 0 0\n0 1 0\n3 0 1 2\n",
                ":3: vertex 0 has 2 coordinates (expected 3)"},
           Case{"OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", ":4: vertex 1: 'x' is not a number"},
           Case{"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
                ":6: face 0 announces 4 corners, its line has 3 more numbers"},
           Case{"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", ":6: face 0: '1.5' is not"},
           Case{"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
                "references vertex -1, out of range"},
           Case{"OFF\n-3 1 0\n", ":2: the vertex count '-3' is not a non-negative integer"},
           Case{"PLY\n3 1 0\n", ":1: not an OFF file"},
           // A corrupt count fails on the missing data, without reserving memory for it.
           Case{"OFF\n99999999999999 1 0\n0 0 0\n",
                "truncated OFF data: the header announces 99999999999999 vertices"},
           Case{"OFF\n", "truncated OFF data: the file ends before the vertex count"},
           Case{"# only a comment\n", "empty OFF file"},
       }) {
    const std::string what = error_of(dir, c.text);
    EXPECT_EQ(what.rfind(path, 0), 0u) << what;
    EXPECT_NE(what.find(c.message), std::string::npos) << what << "\nexpected: " << c.message;
  }
}

TEST(ReadOff, HugeOrNonFiniteNumbersReachTheFiniteCheck) {
  TempDir dir;
  EXPECT_NE(error_of(dir, "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n").find("non-finite"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "OFF\n3 1 0\n0 0 0\n+inf 0 0\n0 1 0\n3 0 1 2\n").find("non-finite"),
            std::string::npos);
}

}  // namespace
}  // namespace cvtmesh
