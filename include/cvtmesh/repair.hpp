// Repairs that keep the shape of a mesh, each counted so the caller can report it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cvtmesh/features.hpp"
#include "cvtmesh/mesh.hpp"

namespace cvtmesh {

struct RepairReport {
  // Vertices at the same point: equal coordinates, or nearly equal (within 1e-12 of the larger of
  // the bounding box diagonal and the largest coordinate), merged into the first of them.
  std::size_t duplicate_vertices_merged = 0;
  std::size_t nearly_equal_vertices_merged = 0;  // of those, the ones not exactly equal
  // Duplicates not merged, because the merge would have made a non-manifold edge or vertex.
  std::size_t duplicate_vertices_kept_apart = 0;
  // Zero-area triangles with one corner strictly inside their long edge, whose removal would
  // open a slit: instead the triangle across that edge is split at that corner (split_caps).
  std::size_t caps_split = 0;
  // The other zero-area triangles (repeated or collinear corners), and caps whose split would
  // leave the surface less manifold than dropping them.
  std::size_t degenerate_triangles_removed = 0;
  std::size_t duplicate_triangles_removed = 0;  // same three vertices, any order or orientation
  std::size_t unreferenced_vertices_removed = 0;
  // Triangles listed the other way round from their neighbours (orient_consistently).
  std::size_t triangles_flipped = 0;

  bool changed() const {
    return duplicate_vertices_merged + caps_split + degenerate_triangles_removed +
               duplicate_triangles_removed + unreferenced_vertices_removed + triangles_flipped >
           0;
  }
  // Whether summary() has anything to say: a change, or duplicates kept apart.
  bool noteworthy() const { return changed() || duplicate_vertices_kept_apart > 0; }
  // "merged 3 duplicate vertices, removed 2 zero-area triangles", or "" if nothing changed.
  std::string summary() const;
};

inline constexpr Index kRemovedVertex = ~Index{0};

// Applies, in this order: merge duplicate vertices (equal or nearly equal coordinates) where that
// stitches the surface and makes no edge or vertex non-manifold, nor a pinch vertex more so than
// its copies were (the others are kept apart and counted), split out zero-area caps (a corner
// strictly inside the long edge) into the triangle across that edge unless that leaves more
// non-manifold edges and vertices than dropping them, drop the zero-area triangles left (exact
// collinearity test), drop duplicate triangles (first one kept), drop unreferenced
// vertices, flip the triangles listed the other way round from most of their patch (the triangles
// joined by manifold edges; a patch no orientation makes consistent stays as it is). Deterministic;
// the kept elements keep their relative order. `new_id`, when given, receives each vertex's id in
// the repaired mesh: a merged duplicate's is that of the vertex it was merged into; a removed
// vertex's is kRemovedVertex.
RepairReport repair_mesh(TriangleMesh& mesh, std::vector<Index>* new_id = nullptr);

// Edges given in a mesh's vertex ids (feature edges read from a file), in the ids of the mesh
// repair_mesh made of it (`new_id`). InvalidArgument, naming the edge, for a vertex out of
// range or removed, or an edge whose two vertices were merged.
std::vector<Edge> edges_after_repair(const std::vector<Edge>& edges,
                                     const std::vector<Index>& new_id);

// Values per vertex of a mesh (target edge lengths read from a file), per vertex of the mesh
// repair_mesh made of it (`new_id`, `repaired_vertex_count`): merged vertices keep the smallest
// of their values; a vertex no value reaches gets 0. InvalidArgument when the counts differ.
std::vector<double> values_after_repair(const std::vector<double>& values,
                                        const std::vector<Index>& new_id,
                                        std::size_t repaired_vertex_count);

// Drops triangles with the same three vertices as an earlier one (any order or orientation),
// keeping the first; returns how many were dropped. One of repair_mesh()'s steps.
std::size_t remove_duplicate_triangles(TriangleMesh& mesh);

// Counts what repair_mesh() would change, without changing the mesh.
RepairReport diagnose_repairs(const TriangleMesh& mesh);

struct HoleFilling {
  std::size_t filled = 0;           // holes closed
  std::size_t triangles_added = 0;  // the triangles that closed them
  // Holes under the length left open: every triangulation of the loop on its own vertices has
  // a degenerate triangle (a slit), or CGAL's would join two vertices that an edge joins
  // already (around a thin part).
  std::size_t left_open = 0;
  std::size_t larger = 0;  // holes at or over the length, or rims (below), left open
  // A vertex has two boundary edges leaving it (two fans meeting at a point): no loop is
  // defined, and none was filled.
  bool loops_undefined = false;
};

// Closes each boundary loop of `mesh` shorter than `max_perimeter` (in the mesh's units) with
// triangles on the loop's own vertices, oriented as the triangles around it (CGAL's hole
// filling: Liepa's triangulation that makes the largest dihedral angle, then the area, smallest).
// A loop at least as long as the square root of its component's area is the rim of a sheet, not
// a hole in it, and stays open whatever the length: a patch over a disc's rim would double it.
// For a mesh that repair_mesh() made: a vertex with two boundary edges leaving it (which repair
// keeps as one copy per fan when it merges duplicates, but leaves as it is when the file has it
// so) leaves every loop open (loops_undefined). Deterministic. InvalidArgument for a negative or
// NaN length.
HoleFilling fill_holes(TriangleMesh& mesh, double max_perimeter);

}  // namespace cvtmesh
