#include "voronoi/multi_nerve.hpp"

#include <algorithm>
#include <numeric>

#include "cvtmesh/repair.hpp"
#include "voronoi/dual_triangle.hpp"
#include "voronoi/kept_chunks.hpp"

namespace cvtmesh {

void MultiNerveBuilder::begin(std::size_t chunks) {
  pieces_.begin(chunks);
  chunks_.assign(chunks, {});
  at_seed_.assign(chunks, {});
}

void MultiNerveBuilder::begin_kept(std::size_t chunks, const std::vector<char>& kept) {
  pieces_.begin_kept(chunks, kept);
  keep_only(kept, chunks_, at_seed_);
}

void MultiNerveBuilder::polygon(std::size_t chunk, const RvdPolygon& poly) {
  pieces_.polygon(chunk, poly);
  const Vec3& seed = rvd_->seeds()[poly.seed];
  for (std::size_t k = 0; k < poly.vertices.size(); ++k) {
    if (const auto t = dual_triangle(poly, k))
      chunks_[chunk].push_back({*t, poly.triangle, poly.vertices[k].point});
    const RvdVertex& v = poly.vertices[k];
    if (v.symbols[0] < 0 && v.symbols[1] < 0 && v.point == seed)  // an input corner
      at_seed_[chunk].push_back({poly.seed, poly.triangle});
  }
}

void MultiNerveBuilder::chunk_done(std::size_t chunk) {
  pieces_.chunk_done(chunk);
  chunks_[chunk].shrink_to_fit();
}

void MultiNerveBuilder::end() {
  pieces_.end();
  const std::vector<Vec3>& seeds = rvd_->seeds();
  // The same polygons of the same seeds: the triangulation is as it was (topology control's
  // search for where to add seeds traverses the seeds its extraction just did).
  if (pieces_.kept_every_chunk() && seeds == seeds_at_end_) return;
  if (keeps_chunks()) seeds_at_end_ = seeds;
  const std::vector<CellPiece>& pieces = pieces_.pieces();
  result_ = {};
  result_.vertices = seeds;
  vertex_seed_.resize(seeds.size());
  std::iota(vertex_seed_.begin(), vertex_seed_.end(), Index{0});
  // The pieces that reach their seed itself: at an input vertex that is stored twice, as where
  // two sheets touch at a point (remesh splits such a vertex, one copy per sheet).
  std::vector<bool> reach_seed(pieces.size(), false);
  for (const auto& found : at_seed_)
    for (const auto& [seed, triangle] : found) reach_seed[pieces_.piece_at(seed, triangle)] = true;
  if (!keeps_chunks()) at_seed_.clear();
  // Each piece's vertex: its seed for the cell's first (largest) piece, a new one otherwise, at
  // the seed too if both pieces reach it (sheets touching at the seed, which still touch there).
  std::vector<Index> vertex(pieces.size());
  for (std::size_t i = 0, first = 0; i < pieces.size(); ++i) {
    const Index seed = pieces[i].seed;
    if (i == 0 || seed != pieces[i - 1].seed) {
      vertex[i] = seed;
      first = i;
      continue;
    }
    vertex[i] = static_cast<Index>(result_.vertices.size());
    const bool touching = reach_seed[i] && reach_seed[first];
    result_.vertices.push_back(touching ? seeds[seed] : pieces[i].largest_centre);
    vertex_seed_.push_back(seed);
  }
  // The three polygons around a type-C vertex lie in the input triangle it is in.
  for (const auto& found : chunks_)
    for (const Found& f : found) {
      Triangle t;
      for (int k = 0; k < 3; ++k) t[k] = vertex[pieces_.piece_at(f.seeds[k], f.triangle)];
      result_.triangles.push_back(t);
    }
  if (!keeps_chunks()) chunks_.clear();
  // A Voronoi edge crossing the surface several times within one piece of each of its three
  // cells gives the same triangle several times.
  remove_duplicate_triangles(result_);
}

std::vector<MultiNerveBuilder::Crossing> MultiNerveBuilder::crossings(
    const std::vector<Triangle>& wanted) const {
  std::vector<Crossing> out;
  const std::vector<Vec3>& seeds = rvd_->seeds();
  for (const auto& found : chunks_)
    for (const Found& f : found)
      if (std::binary_search(wanted.begin(), wanted.end(), f.seeds))
        out.push_back({f.point, distance(f.point, seeds[f.seeds[0]])});
  return out;
}

}  // namespace cvtmesh
