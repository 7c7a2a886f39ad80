// Every mesh in ../shared/data reads, and its counts equal those its README states.
// The README's table is parsed here, so a mesh added there is checked without code changes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>

#include "cvtmesh/io.hpp"
#include "cvtmesh/rvd.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "cvtmesh/sampling.hpp"
#include "cvtmesh/topology.hpp"
#include "support/shared_data.hpp"
#include "support/temp_dir.hpp"

namespace cvtmesh {
namespace {

struct Expected {
  std::string file;
  long long vertices, triangles, boundary_loops, euler, components, nonmanifold_edges;
};

long long number(std::string s) {
  std::erase(s, ',');
  return std::stoll(s);
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::stringstream in(row);
  std::string cell;
  std::getline(in, cell, '|');  // before the first bar
  while (std::getline(in, cell, '|')) {
    const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
    out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  return out;
}

// Rows of the table "| file | size | model | source | license | V | F | boundary | genus / χ |
// components | edge-manifold | notes |".
std::vector<Expected> expected_counts(const std::filesystem::path& readme) {
  std::vector<Expected> rows;
  std::istringstream text(testing::read_file(readme));
  const std::regex first_number(R"(-?[0-9][0-9,]*)");
  std::string line;
  while (std::getline(text, line)) {
    if (!line.starts_with("| `")) continue;
    const auto c = cells(line);
    if (c.size() < 11) continue;
    auto leading = [&](const std::string& cell) {
      std::smatch m;
      return std::regex_search(cell, m, first_number) ? number(m.str()) : -1;
    };
    Expected e;
    e.file = c[0].substr(1, c[0].find('`', 1) - 1);
    e.vertices = number(c[5]);
    e.triangles = leading(c[6]);
    e.boundary_loops = c[7] == "closed" ? 0 : leading(c[7]);
    e.euler = number(c[8].substr(c[8].rfind('/') + 1));
    e.components = number(c[9]);
    e.nonmanifold_edges = c[10].starts_with("no") ? leading(c[10].substr(2)) : 0;
    rows.push_back(e);
  }
  return rows;
}

TEST(SharedData, EveryMeshMatchesTheCountsOfItsReadme) {
  const auto dir = testing::shared_data();
  if (!std::filesystem::exists(dir / "README.md"))
    GTEST_SKIP() << "shared test meshes not found at " << dir
                 << " (clone ../shared beside the repository, or set CVTMESH_SHARED_DATA)";
  const std::vector<Expected> rows = expected_counts(dir / "README.md");
  ASSERT_GE(rows.size(), 10u) << "could not parse the README's table";
  std::size_t meshes_in_folder = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (format_from_extension(entry.path())) ++meshes_in_folder;
  EXPECT_EQ(rows.size(), meshes_in_folder) << "every mesh file should have a row in the README";
  for (const Expected& e : rows) {
    SCOPED_TRACE(e.file);
    const TopologyReport t = analyze_topology(read_mesh(dir / e.file));
    EXPECT_EQ(static_cast<long long>(t.vertices), e.vertices);
    EXPECT_EQ(static_cast<long long>(t.triangles), e.triangles);
    EXPECT_EQ(static_cast<long long>(t.boundary_loops), e.boundary_loops);
    EXPECT_EQ(t.euler_characteristic, e.euler);
    EXPECT_EQ(static_cast<long long>(t.components), e.components);
    EXPECT_EQ(static_cast<long long>(t.nonmanifold_edges), e.nonmanifold_edges);
  }
}

TEST(SharedData, RvdCellsTileEveryMesh) {
  const auto dir = testing::shared_data();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared test meshes not found at " << dir;
  std::size_t meshes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (!format_from_extension(entry.path())) continue;
    SCOPED_TRACE(entry.path().filename().string());
    const TriangleMesh mesh = read_mesh(entry.path());
    const RestrictedVoronoiDiagram rvd(mesh, sample_surface(mesh, 2000, 1));
    CellIntegrator integrator(rvd);
    rvd.traverse(integrator);
    const double area = surface_area(mesh);
    EXPECT_NEAR(integrator.result().total_mass, area, 1e-12 * area);
    ++meshes;
  }
  EXPECT_GT(meshes, 0u);
}

}  // namespace
}  // namespace cvtmesh
