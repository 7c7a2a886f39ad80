// CVT integrals over the RVD (paper §4.2, eq. 5-6): each clipped polygon is split into a fan of
// triangles, on which ρ (linear over the input triangle) and ‖x − x_i‖² are integrated exactly.
#include <tbb/parallel_for.h>

#include <algorithm>

#include "cvtmesh/errors.hpp"
#include "cvtmesh/rvd_consumers.hpp"
#include "geometry/unit_vector.hpp"

namespace cvtmesh {

namespace {

// A density linear over a triangle, ρ(p) = ρ(c0) + slope·(p − c0) for p in its plane, from its
// values at the corners: read at a polygon's vertices with one dot product each, where
// barycentric coordinates took three cross products each.
struct LinearDensity {
  Vec3 origin, slope;
  double base = 0;

  LinearDensity(const std::array<Vec3, 3>& c, const std::array<double, 3>& r) : origin(c[0]) {
    // λ1 = (e2 × n)·(p − c0) / ‖n‖², λ2 = (n × e1)·(p − c0) / ‖n‖².
    const Vec3 e1 = c[1] - c[0], e2 = c[2] - c[0], n = cross(e1, e2);
    const double n2 = dot(n, n);
    if (n2 == 0) {  // no plane: the corners' mean
      base = (r[0] + r[1] + r[2]) / 3;
      return;
    }
    slope = (1 / n2) * ((r[1] - r[0]) * cross(e2, n) + (r[2] - r[0]) * cross(n, e1));
    base = r[0];
  }
  double at(const Vec3& p) const { return base + dot(slope, p - origin); }
};

// ∫ over triangle p of ρ (linear, values r) times 1, x and ‖x − seed‖², with
// ∫ λ_a λ_b λ_c = 2A·a!b!c!/5! for the exponents of the barycentric coordinates.
struct FanIntegral {
  double mass, energy;
  Vec3 moment;
};

// The area of triangle (a, b, c) signed along the unit normal n: a polygon's fan sums to its
// area from any first vertex, even where rounding bends it a little (the fan triangles folded
// over then subtract).
double signed_area(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
  return 0.5 * dot(cross(b - a, c - a), n);
}

FanIntegral integrate_triangle(const std::array<Vec3, 3>& p, const std::array<double, 3>& r,
                               const Vec3& seed, const Vec3& n) {
  const double area = signed_area(p[0], p[1], p[2], n);
  const double r_sum = r[0] + r[1] + r[2];
  FanIntegral f;
  f.mass = area * r_sum / 3;
  f.moment = (area / 12) * ((r_sum + r[0]) * p[0] + (r_sum + r[1]) * p[1] + (r_sum + r[2]) * p[2]);
  // Σ_m r_m Σ_{a,b} (u_a·u_b) ∫λ_m λ_a λ_b, the integral being A/10, A/30 or A/60 when m, a, b
  // take one, two or three distinct values: 60/A times it is, per m, S + T + 2 u_m·U + 2‖u_m‖²
  // with U = Σ u_a, S = ‖U‖², T = Σ ‖u_a‖² (the weights 6, 2, 1 are 1 + [a = b] + [a = m] +
  // [b = m] + 2[a = b = m]).
  const Vec3 u[3] = {p[0] - seed, p[1] - seed, p[2] - seed};
  const Vec3 U = u[0] + u[1] + u[2];
  double T = 0, weighted = 0;
  for (int m = 0; m < 3; ++m) {
    const double uu = dot(u[m], u[m]);
    T += uu;
    weighted += r[m] * (dot(u[m], U) + uu);
  }
  const double energy = (dot(U, U) + T) * r_sum + 2 * weighted;
  f.energy = energy * area / 60;
  return f;
}

// The same for ρ = 1, the common case, in a third of the operations: ∫‖x − seed‖² over a
// triangle is A/6 (Σ_a ‖u_a‖² + Σ_{a<b} u_a·u_b) for its corners u relative to the seed.
FanIntegral integrate_uniform(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& seed,
                              const Vec3& n) {
  const double area = signed_area(p0, p1, p2, n);
  const Vec3 u0 = p0 - seed, u1 = p1 - seed, u2 = p2 - seed;
  const Vec3 sum = u0 + u1 + u2;
  // Σ_a ‖u_a‖² + Σ_{a<b} u_a·u_b = (‖Σ u‖² + Σ ‖u_a‖²) / 2.
  const double energy = (dot(sum, sum) + dot(u0, u0) + dot(u1, u1) + dot(u2, u2)) / 2;
  return {area, energy * area / 6, (area / 3) * (p0 + p1 + p2)};
}

}  // namespace

std::vector<Vec3> CellIntegrals::gradient(const std::vector<Vec3>& seeds) const {
  std::vector<Vec3> g(seeds.size());
  for (std::size_t s = 0; s < seeds.size(); ++s) g[s] = 2 * (mass[s] * seeds[s]) - 2 * moment[s];
  return g;
}

std::vector<Vec3> unit_normals(const TriangleMesh& surface) {
  std::vector<Vec3> normals(surface.triangles.size());
  tbb::parallel_for(std::size_t{0}, normals.size(), [&](std::size_t t) {
    const auto [a, b, c] = surface.corners(t);
    normals[t] = unit_normal(a, b, c);
  });
  return normals;
}

CellIntegrator::CellIntegrator(const RestrictedVoronoiDiagram& rvd, std::span<const double> density,
                               std::span<const Vec3> unit_normals)
    : rvd_(rvd), density_(density), unit_normals_(unit_normals) {
  if (!density_.empty() && density_.size() != rvd.surface().vertices.size())
    throw InvalidArgument("density needs one value per input vertex");
  if (!unit_normals_.empty() && unit_normals_.size() != rvd.surface().triangles.size())
    throw InvalidArgument("unit normals need one per input triangle");
  if (std::any_of(density_.begin(), density_.end(), [](double r) { return !(r > 0); }))
    throw InvalidArgument("density values must be positive and finite");
}

void CellIntegrator::begin(std::size_t chunks) {
  chunks_.assign(chunks, {});
  done_.assign(chunks, 0);
  added_ = 0;
  const std::size_t n = rvd_.seeds().size();
  result_ = {};
  result_.mass.assign(n, 0);
  result_.energy.assign(n, 0);
  result_.moment.assign(n, {});
}

void CellIntegrator::polygon(std::size_t chunk, const RvdPolygon& poly) {
  const Vec3& seed = rvd_.seeds()[poly.seed];
  const auto& v = poly.vertices;
  // The input triangle's normal, stored or computed alike: the same sums either way.
  const auto normal = [&] {
    if (!unit_normals_.empty()) return unit_normals_[poly.triangle];
    const auto [a, b, c] = rvd_.surface().corners(poly.triangle);
    return unit_normal(a, b, c);
  };
  const Vec3 n = normal();
  Contribution c{poly.seed, 0, 0, {}};
  if (density_.empty()) {
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const FanIntegral f = integrate_uniform(v[0].point, v[k].point, v[k + 1].point, seed, n);
      c.mass += f.mass;
      c.energy += f.energy;
      c.moment += f.moment;
    }
    chunks_[chunk].push_back(c);
    return;
  }
  const Triangle& f = rvd_.surface().triangles[poly.triangle];
  const LinearDensity rho(rvd_.surface().corners(poly.triangle),
                          {density_[f[0]], density_[f[1]], density_[f[2]]});
  const double r0 = rho.at(v[0].point);
  double r_prev = rho.at(v[1].point);
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const double r_next = rho.at(v[k + 1].point);
    const FanIntegral f =
        integrate_triangle({v[0].point, v[k].point, v[k + 1].point}, {r0, r_prev, r_next}, seed, n);
    c.mass += f.mass;
    c.energy += f.energy;
    c.moment += f.moment;
    r_prev = r_next;
  }
  chunks_[chunk].push_back(c);
}

void CellIntegrator::chunk_done(std::size_t chunk) {
  const std::lock_guard lock(adding_);
  done_[chunk] = 1;
  add_done_chunks();
}

void CellIntegrator::add_done_chunks() {
  // Chunks in order, each in its own order: the same sums for any thread count.
  for (; added_ < chunks_.size() && done_[added_]; ++added_) {
    for (const Contribution& c : chunks_[added_]) {
      result_.mass[c.seed] += c.mass;
      result_.energy[c.seed] += c.energy;
      result_.moment[c.seed] += c.moment;
    }
    std::vector<Contribution>().swap(chunks_[added_]);
  }
}

void CellIntegrator::end() {
  std::fill(done_.begin(), done_.end(), 1);  // a driver need not report chunks done
  add_done_chunks();
  for (std::size_t s = 0; s < result_.mass.size(); ++s) {
    result_.total_mass += result_.mass[s];
    result_.total_energy += result_.energy[s];
  }
  chunks_.clear();
  done_.clear();
}

}  // namespace cvtmesh
