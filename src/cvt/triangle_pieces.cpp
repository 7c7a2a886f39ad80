#include "cvt/triangle_pieces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace cvtmesh {

namespace {

// Triangles no longer than this many spacings stay whole: they reach a few cells beyond the
// cells that cover them, as all triangles did before.
constexpr double kCutAbove = 8;
// Pieces' longest edges, in spacings: a few cells, so that the pieces add few polygons (pieces
// half a spacing long made 8 times the polygons of the whole facets on spool.off at 10k, and the
// steps no faster; 2 spacings, 1.3 times).
constexpr double kPieceLength = 4;

}  // namespace

TrianglePieces::TrianglePieces(const TriangleMesh& surface, double spacing)
    : surface_(surface), cut_(surface.triangles.size(), 0), piece_length_(kPieceLength * spacing) {
  // No spacing (no area, no seed) cuts nothing: the pieces would never get short enough.
  if (!(spacing > 0 && std::isfinite(spacing))) return;
  for (std::size_t t = 0; t < cut_.size(); ++t) {
    const auto [a, b, c] = surface.corners(t);
    cut_[t] = std::max({distance(a, b), distance(b, c), distance(c, a)}) > kCutAbove * spacing;
  }
}

void TrianglePieces::add_pieces(Index t, std::span<const Ball> balls,
                                const std::vector<double>* rho, TriangleMesh& patch,
                                std::vector<double>& density) const {
  // A corner of a piece: where it is, and ρ there (linear over t: midpoints average it).
  struct Corner {
    Vec3 p;
    double rho;
  };
  std::map<Vec3, Index> id;  // the pieces' vertices added so far, by position
  const auto vertex = [&](const Corner& c) {
    const auto [it, added] = id.emplace(c.p, static_cast<Index>(patch.vertices.size()));
    if (added) {
      patch.vertices.push_back(c.p);
      if (rho) density.push_back(c.rho);
    }
    return it->second;
  };
  // Longest-edge bisection, which keeps the pieces' shapes (slivers give short pieces along
  // them, not thinner slivers), down to pieces no longer than piece_length_; a part that meets
  // no ball is dropped whole. The midpoint of an edge is the same whichever side asks.
  const auto cut = [&](const auto& self, const std::array<Corner, 3>& c) -> void {
    const Vec3 center = (1.0 / 3) * (c[0].p + c[1].p + c[2].p);
    const double radius =
        std::max({distance(c[0].p, center), distance(c[1].p, center), distance(c[2].p, center)});
    // Rounding: a part that only touches a ball goes in too.
    if (std::none_of(balls.begin(), balls.end(), [&](const Ball& ball) {
          return distance(ball.center, center) <= (ball.radius + radius) * (1 + 1e-9);
        }))
      return;
    int longest = 0;  // edge e joins corners e and e + 1
    double length = 0;
    for (int e = 0; e < 3; ++e)
      if (const double l = distance(c[e].p, c[(e + 1) % 3].p); l > length) length = l, longest = e;
    if (length <= piece_length_) {
      patch.triangles.push_back({vertex(c[0]), vertex(c[1]), vertex(c[2])});
      return;
    }
    const Corner& from = c[longest];
    const Corner& to = c[(longest + 1) % 3];
    const Corner& apex = c[(longest + 2) % 3];
    const Corner mid{0.5 * (from.p + to.p), 0.5 * (from.rho + to.rho)};
    // Both halves keep t's orientation: (from, mid, apex) and (mid, to, apex).
    self(self, {from, mid, apex});
    self(self, {mid, to, apex});
  };
  const Triangle& f = surface_.triangles[t];
  std::array<Corner, 3> corners;
  for (int m = 0; m < 3; ++m) corners[m] = {surface_.vertices[f[m]], rho ? (*rho)[f[m]] : 0.0};
  cut(cut, corners);
}

}  // namespace cvtmesh
