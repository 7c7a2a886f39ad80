// Meshes generated in code, so core tests and benchmarks run without any data files.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "cvtmesh/mesh.hpp"

namespace cvtmesh::testing {

// Unit icosahedron subdivided `levels` times, vertices on the sphere of `radius`:
// 20·4^levels triangles, closed, genus 0.
TriangleMesh icosphere(int levels, double radius = 1.0);

// Torus around z with major radius R and minor radius r: 2·nu·nv triangles, genus 1.
TriangleMesh torus(double R, double r, int nu, int nv);

// Surface of the cube [-1,1]^3, each face an n×n grid: 12·n² triangles, closed, genus 0.
TriangleMesh cube(int n);

// Flat unit disk in z = 0: a centre vertex and `rings` rings of `sectors` vertices; open,
// one boundary loop, Euler characteristic 1.
TriangleMesh disk(int rings, int sectors);

// Unit upper hemisphere: a pole vertex and `rings` latitudes of `sectors` vertices down to the
// equator; open, one boundary loop, Euler characteristic 1.
TriangleMesh hemisphere(int rings, int sectors);

// Closed cylinder of radius 1 around z, from z = -1 to 1: side grid of `rings` × `sectors`
// quads, each cap a fan around its centre; genus 0, sharp 90° rims.
TriangleMesh cylinder(int rings, int sectors);

// An nx × ny grid of quads over the unit square (u, v), each split in two, its vertices placed
// by `at`: a flat sheet, a strip, a wedge.
TriangleMesh mapped_grid(int nx, int ny, const std::function<Vec3(double, double)>& at);

// A closed knife: the prism over a thin isosceles triangle, its edge of `deg` degrees along the
// y axis from (0, 0, 0) to (0, 1, 0), its back at x = 1; each side of the profile in `n` steps,
// `n` steps along y, the two ends fans from the profile's centroid.
TriangleMesh knife(double deg, int n);

// A flat sheet in z = 0 ending in a tip of `deg` degrees at the origin: the tip vertex, then
// `rings` rings of `across` + 1 vertices out to `radius` (ring i, step j is vertex
// wedge_sheet_vertex(i, j, across), at radius i / rings of `radius` and angle j / across of
// `deg`); open, one boundary loop, the tip a corner of its two straight sides.
TriangleMesh wedge_sheet(double deg, double radius, int rings, int across);
// The id in wedge_sheet of ring i (1 to rings), step j (0 to across).
inline Index wedge_sheet_vertex(int i, int j, int across) {
  return static_cast<Index>(1 + (i - 1) * (across + 1) + j);
}

// The unit square in z = 0 as 3 × 3 blocks of n × n quads, without the centre block and the
// top-right one: the two holes meet at the point (2/3, 2/3), which is stored twice, once for each
// fan of triangles around it (as repair leaves a vertex that merging would make non-manifold).
// One component, one boundary loop that touches itself there, Euler characteristic 1.
TriangleMesh sheet_pinched_at_a_point(int n);

// A torus around z (major radius 1) whose tube narrows to a point at angle 0, its radius
// r √sin(u / 2) at angle u: one component, closed, Euler characteristic 1, the point one vertex
// with two fans (two rounded ends touching). `nu` steps around, `nv` around the tube.
TriangleMesh pinched_torus(double r, int nu, int nv);

// A torus around z (major radius 1, tube radius r) whose tube narrows smoothly to radius `neck`
// around angle 0 (within 0.3 radians of it): closed, genus 1, its one handle's throat a loop
// 2π neck round. `nu` steps around, `nv` around the tube.
TriangleMesh necked_torus(double r, double neck, int nu, int nv);

// A Möbius strip of n quads (each split in two) around the unit circle, 0.4 wide: its ends
// glued with a half twist. One boundary loop, not orientable.
TriangleMesh moebius_strip(int n);

// `mesh` with up to `holes` holes of one triangle each: every `step`-th triangle that shares no
// vertex with an earlier hole or the boundary (a scan with dropouts; each hole is one more
// boundary loop).
TriangleMesh with_one_triangle_holes(TriangleMesh mesh, std::size_t holes, std::size_t step);

// `mesh` with a T-junction stitched shut by zero-area triangles, as CAD exports and game assets
// have: triangle `t` (a, b, x) is split into a fan from x at `points` points evenly along a-b
// (exact for a power of two plus one intervals and coordinates on a binary grid), the triangle
// across a-b is left whole, and the slit between them is closed by a fan of caps from a, each
// zero-area with a corner strictly inside its long edge. Closed and manifold where `mesh` is.
TriangleMesh with_t_junction(TriangleMesh mesh, std::size_t t, int points);

// Appends the quad a-b-c-d (in that order round it) as triangles (a, b, c) and (a, c, d).
void add_quad(TriangleMesh& mesh, Index a, Index b, Index c, Index d);

// The planes z = 0 and x = 0 over [-1, 1]², crossing along the y axis, each cut across x (and z)
// at `cuts` (increasing, from -1 to 1) into strips of two triangles: two components, each a disc.
// With cuts {-1, -0.01, 0.01, 1}, the triangles that cross are the middle strips', 0.02 wide.
TriangleMesh crossing_planes(const std::vector<double>& cuts);

// Both meshes in one, `b` after `a` (indices of `b` shifted).
TriangleMesh concatenate(const TriangleMesh& a, const TriangleMesh& b);

// `mesh` with every vertex moved by `offset` and scaled by `scale` about the origin first.
TriangleMesh transformed(TriangleMesh mesh, double scale, const Vec3& offset = {});

// `mesh` with each vertex moved at random by up to `amount` in each coordinate, then put back on
// the unit sphere (along the ray from the origin); the same `seed`, the same moves.
TriangleMesh jittered_on_sphere(TriangleMesh mesh, double amount, std::uint64_t seed);

// The same surface with its vertex ids and its triangles in a random order (fixed by `seed`);
// `new_id[v]`, if given, receives each vertex's new id.
TriangleMesh shuffled(const TriangleMesh& mesh, std::uint64_t seed,
                      std::vector<Index>* new_id = nullptr);

}  // namespace cvtmesh::testing
