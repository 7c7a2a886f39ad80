#include "support/shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <tuple>

#include "cvtmesh/repair.hpp"

namespace cvtmesh::testing {

namespace {

Vec3 normalized(const Vec3& v) {
  return (1.0 / norm(v)) * v;
}

}  // namespace

TriangleMesh icosphere(int levels, double radius) {
  const double p = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh m;
  m.vertices = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3& v : m.vertices) v = normalized(v);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    auto mid = [&](Index a, Index b) {
      auto [it, fresh] = midpoint.try_emplace({std::min(a, b), std::max(a, b)}, 0);
      if (fresh) {
        it->second = static_cast<Index>(m.vertices.size());
        m.vertices.push_back(normalized(0.5 * (m.vertices[a] + m.vertices[b])));
      }
      return it->second;
    };
    std::vector<Triangle> finer;
    for (const Triangle& t : m.triangles) {
      const Index ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      for (Triangle child : {Triangle{t[0], ab, ca}, Triangle{t[1], bc, ab}, Triangle{t[2], ca, bc},
                             Triangle{ab, bc, ca}})
        finer.push_back(child);
    }
    m.triangles = std::move(finer);
  }
  for (Vec3& v : m.vertices) v = radius * v;
  return m;
}

TriangleMesh torus(double R, double r, int nu, int nv) {
  TriangleMesh m;
  const double tau = 2 * std::numbers::pi;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = tau * i / nu, v = tau * j / nv;
      m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u),
                            (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  }
  auto id = [&](int i, int j) { return static_cast<Index>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      add_quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  return m;
}

TriangleMesh cube(int n) {
  TriangleMesh m;
  // Each face: a fixed axis at ±1 and two free axes on a grid. Shared edges produce bit-equal
  // coordinates, merged below.
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {-1.0, 1.0}) {
      const Index base = static_cast<Index>(m.vertices.size());
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          double c[3];
          c[axis] = side;
          c[(axis + 1) % 3] = -1 + 2.0 * i / n;
          c[(axis + 2) % 3] = -1 + 2.0 * j / n;
          m.vertices.push_back({c[0], c[1], c[2]});
        }
      }
      auto id = [&](int i, int j) { return base + static_cast<Index>(i * (n + 1) + j); };
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          // (axis+1, axis+2, axis) is right-handed: counter-clockwise seen from +axis.
          if (side > 0) {
            add_quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
          } else {
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
            m.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
          }
        }
      }
    }
  }
  repair_mesh(m);
  return m;
}

TriangleMesh disk(int rings, int sectors) {
  TriangleMesh m;
  m.vertices.push_back({0, 0, 0});
  const double tau = 2 * std::numbers::pi;
  for (int k = 1; k <= rings; ++k) {
    for (int s = 0; s < sectors; ++s) {
      const double radius = static_cast<double>(k) / rings, a = tau * s / sectors;
      m.vertices.push_back({radius * std::cos(a), radius * std::sin(a), 0});
    }
  }
  auto id = [&](int k, int s) {
    return k == 0 ? Index{0} : static_cast<Index>(1 + (k - 1) * sectors + (s % sectors));
  };
  for (int s = 0; s < sectors; ++s) m.triangles.push_back({0, id(1, s), id(1, s + 1)});
  for (int k = 1; k < rings; ++k) {
    for (int s = 0; s < sectors; ++s) {
      add_quad(m, id(k, s), id(k + 1, s), id(k + 1, s + 1), id(k, s + 1));
    }
  }
  return m;
}

TriangleMesh sheet_pinched_at_a_point(int n) {
  TriangleMesh m;
  std::map<std::tuple<int, int, bool>, Index> id;
  const auto vertex = [&](int i, int j, bool second_copy) {
    const auto [at, added] = id.emplace(std::tuple(i, j, second_copy), m.vertices.size());
    if (added) m.vertices.push_back({i / (3.0 * n), j / (3.0 * n), 0});
    return at->second;
  };
  for (int bi = 0; bi < 3; ++bi)
    for (int bj = 0; bj < 3; ++bj) {
      if ((bi == 1 && bj == 1) || (bi == 2 && bj == 2)) continue;
      // The right-middle block's fan around the pinch gets the second copy.
      const auto corner = [&](int i, int j) {
        return vertex(i, j, bi == 2 && bj == 1 && i == 2 * n && j == 2 * n);
      };
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const int i = bi * n + a, j = bj * n + b;
          add_quad(m, corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1));
        }
    }
  return m;
}

TriangleMesh with_one_triangle_holes(TriangleMesh mesh, std::size_t holes, std::size_t step) {
  std::vector<bool> touched(mesh.vertices.size(), false);
  std::map<Edge, int> uses;
  for (const Triangle& f : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])}];
  for (const auto& [e, n] : uses)
    if (n == 1) touched[e[0]] = touched[e[1]] = true;
  std::vector<Triangle> kept;
  std::size_t made = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    if (made < holes && t % step == 0 && !touched[f[0]] && !touched[f[1]] && !touched[f[2]]) {
      for (const Index v : f) touched[v] = true;
      ++made;
    } else {
      kept.push_back(f);
    }
  }
  mesh.triangles = std::move(kept);
  return mesh;
}

TriangleMesh with_t_junction(TriangleMesh mesh, std::size_t t, int points) {
  const auto [a, b, x] = mesh.triangles[t];
  std::vector<Index> along{a};  // a, the points in order, b
  for (int k = 1; k <= points; ++k) {
    const double s = static_cast<double>(k) / (points + 1);
    along.push_back(static_cast<Index>(mesh.vertices.size()));
    mesh.vertices.push_back((1 - s) * mesh.vertices[a] + s * mesh.vertices[b]);
  }
  along.push_back(b);
  mesh.triangles[t] = {along[0], along[1], x};
  for (std::size_t k = 1; k + 1 < along.size(); ++k)
    mesh.triangles.push_back({along[k], along[k + 1], x});
  // The caps: (a, b, m_k), then (a, m_k, m_k-1) down to (a, m_2, m_1).
  for (std::size_t k = along.size() - 1; k >= 2; --k)
    mesh.triangles.push_back({a, along[k], along[k - 1]});
  return mesh;
}

TriangleMesh moebius_strip(int n) {
  TriangleMesh m;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    for (double w : {-0.2, 0.2}) {
      const double r = 1 + w * std::cos(a / 2);
      m.vertices.push_back({r * std::cos(a), r * std::sin(a), w * std::sin(a / 2)});
    }
  }
  for (int i = 0; i < n; ++i) {
    const auto a0 = static_cast<Index>(2 * i), a1 = static_cast<Index>(2 * i + 1);
    const bool last = i == n - 1;
    const Index b0 = last ? 1 : a0 + 2, b1 = last ? 0 : a0 + 3;  // the twist swaps sides
    m.triangles.push_back({a0, b0, b1});
    m.triangles.push_back({a0, b1, a1});
  }
  return m;
}

TriangleMesh pinched_torus(double r, int nu, int nv) {
  TriangleMesh m;
  m.vertices.push_back({1, 0, 0});  // the pinch
  const double tau = 2 * std::numbers::pi;
  for (int i = 1; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = tau * i / nu, v = tau * j / nv, radius = r * std::sqrt(std::sin(u / 2));
      const double R = 1 + radius * std::cos(v);
      m.vertices.push_back({R * std::cos(u), R * std::sin(u), radius * std::sin(v)});
    }
  const auto id = [&](int i, int j) { return static_cast<Index>(1 + (i - 1) * nv + (j % nv)); };
  for (int j = 0; j < nv; ++j) {
    m.triangles.push_back({0, id(1, j), id(1, j + 1)});
    m.triangles.push_back({0, id(nu - 1, j + 1), id(nu - 1, j)});
  }
  for (int i = 1; i + 1 < nu; ++i)
    for (int j = 0; j < nv; ++j)
      add_quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

TriangleMesh necked_torus(double r, double neck, int nu, int nv) {
  TriangleMesh m;
  const double tau = 2 * std::numbers::pi;
  for (int i = 0; i < nu; ++i) {
    const double u = tau * i / nu, off = std::min(u, tau - u) / 0.3;
    const double bump = std::max(0.0, 1 - off * off), radius = r - (r - neck) * bump * bump;
    for (int j = 0; j < nv; ++j) {
      const double v = tau * j / nv, R = 1 + radius * std::cos(v);
      m.vertices.push_back({R * std::cos(u), R * std::sin(u), radius * std::sin(v)});
    }
  }
  const auto id = [&](int i, int j) { return static_cast<Index>((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      add_quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

TriangleMesh mapped_grid(int nx, int ny, const std::function<Vec3(double, double)>& at) {
  TriangleMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.vertices.push_back(at(static_cast<double>(i) / nx, static_cast<double>(j) / ny));
  const auto id = [&](int i, int j) { return static_cast<Index>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      add_quad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

TriangleMesh hemisphere(int rings, int sectors) {
  TriangleMesh m;
  m.vertices.push_back({0, 0, 1});
  const double tau = 2 * std::numbers::pi;
  for (int k = 1; k <= rings; ++k) {
    const double polar = tau / 4 * k / rings;
    for (int s = 0; s < sectors; ++s) {
      const double a = tau * s / sectors;
      m.vertices.push_back(
          {std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar)});
    }
  }
  // The same connectivity as the disk: ring k of the disk is latitude k here.
  m.triangles = disk(rings, sectors).triangles;
  return m;
}

TriangleMesh cylinder(int rings, int sectors) {
  TriangleMesh m;
  const double tau = 2 * std::numbers::pi;
  for (int k = 0; k <= rings; ++k) {
    for (int s = 0; s < sectors; ++s) {
      const double a = tau * s / sectors;
      m.vertices.push_back({std::cos(a), std::sin(a), -1 + 2.0 * k / rings});
    }
  }
  const auto bottom = static_cast<Index>(m.vertices.size());
  m.vertices.push_back({0, 0, -1});
  m.vertices.push_back({0, 0, 1});
  auto id = [&](int k, int s) { return static_cast<Index>(k * sectors + (s % sectors)); };
  for (int k = 0; k < rings; ++k) {
    for (int s = 0; s < sectors; ++s) {
      add_quad(m, id(k, s), id(k, s + 1), id(k + 1, s + 1), id(k + 1, s));
    }
  }
  for (int s = 0; s < sectors; ++s) {
    m.triangles.push_back({bottom, id(0, s + 1), id(0, s)});
    m.triangles.push_back({bottom + 1, id(rings, s), id(rings, s + 1)});
  }
  return m;
}

TriangleMesh knife(double deg, int n) {
  const double half = std::tan(deg * std::numbers::pi / 180 / 2);
  // The profile: the edge at the origin, the back at x = 1, each side in n steps.
  const std::array<std::array<double, 2>, 3> corner{{{0, 0}, {1, half}, {1, -half}}};
  std::vector<std::array<double, 2>> profile;
  for (int i = 0; i < 3; ++i) {
    const auto& a = corner[i];
    const auto& b = corner[(i + 1) % 3];
    for (int k = 0; k < n; ++k)
      profile.push_back({a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n});
  }
  const auto m = static_cast<Index>(profile.size());
  TriangleMesh knife;
  for (int j = 0; j <= n; ++j)
    for (const auto& p : profile)
      knife.vertices.push_back({p[0], static_cast<double>(j) / n, p[1]});
  for (Index j = 0; j < static_cast<Index>(n); ++j)
    for (Index i = 0; i < m; ++i) {
      const Index a = j * m + i, b = j * m + (i + 1) % m;
      knife.triangles.push_back({a, b, b + m});
      knife.triangles.push_back({a, b + m, a + m});
    }
  for (const int j : {0, n}) {  // the ends, fans from the profile's centroid
    const auto centre = static_cast<Index>(knife.vertices.size());
    knife.vertices.push_back({2.0 / 3, static_cast<double>(j) / n, 0});
    for (Index i = 0; i < m; ++i) {
      const Index a = static_cast<Index>(j) * m + i, b = static_cast<Index>(j) * m + (i + 1) % m;
      knife.triangles.push_back(j == 0 ? Triangle{centre, b, a} : Triangle{centre, a, b});
    }
  }
  return knife;
}

TriangleMesh wedge_sheet(double deg, double radius, int rings, int across) {
  const double wedge = deg * std::numbers::pi / 180;
  const auto at = [&](int i, int j) { return wedge_sheet_vertex(i, j, across); };
  TriangleMesh sheet;
  sheet.vertices.push_back({0, 0, 0});
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j <= across; ++j) {
      const double r = radius * i / rings, a = wedge * j / across;
      sheet.vertices.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
  for (int j = 0; j < across; ++j) sheet.triangles.push_back({0, at(1, j), at(1, j + 1)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < across; ++j)
      add_quad(sheet, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return sheet;
}

void add_quad(TriangleMesh& mesh, Index a, Index b, Index c, Index d) {
  mesh.triangles.push_back({a, b, c});
  mesh.triangles.push_back({a, c, d});
}

TriangleMesh concatenate(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh m = a;
  const Index shift = static_cast<Index>(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles) m.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  return m;
}

TriangleMesh transformed(TriangleMesh mesh, double scale, const Vec3& offset) {
  for (Vec3& v : mesh.vertices) v = scale * v + offset;
  return mesh;
}

TriangleMesh crossing_planes(const std::vector<double>& cuts) {
  const auto plane = [&](bool vertical) {
    TriangleMesh m;
    for (const double a : cuts)
      for (const double y : {-1.0, 1.0})
        m.vertices.push_back(vertical ? Vec3{0, y, a} : Vec3{a, y, 0});
    for (Index i = 0; i + 1 < cuts.size(); ++i) {
      m.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
      m.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    return m;
  };
  return concatenate(plane(false), plane(true));
}

TriangleMesh shuffled(const TriangleMesh& mesh, std::uint64_t seed, std::vector<Index>* new_id) {
  std::mt19937_64 random(seed);
  std::vector<Index> id(mesh.vertices.size());
  std::iota(id.begin(), id.end(), Index{0});
  std::shuffle(id.begin(), id.end(), random);
  TriangleMesh out;
  out.vertices.resize(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) out.vertices[id[v]] = mesh.vertices[v];
  out.triangles = mesh.triangles;
  for (Triangle& t : out.triangles)
    for (Index& v : t) v = id[v];
  std::shuffle(out.triangles.begin(), out.triangles.end(), random);
  if (new_id) *new_id = std::move(id);
  return out;
}

TriangleMesh jittered_on_sphere(TriangleMesh mesh, double amount, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (Vec3& v : mesh.vertices) {
    const Vec3 moved = v + Vec3{u(random), u(random), u(random)};
    v = (1 / norm(moved)) * moved;
  }
  return mesh;
}

}  // namespace cvtmesh::testing
