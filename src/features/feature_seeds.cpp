#include "features/feature_seeds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

#include "cvtmesh/errors.hpp"
#include "geometry/point_tree.hpp"

namespace cvtmesh {

namespace {

// The shortest missing link, in spacings, that a new seed splits (see mend_missing_links).
constexpr double kShortestSplitLink = 0.9;

// Per curve: whether another open curve joins the same two corners, so that the two make a
// loop (a small hole with two corners, a rim cut twice) whose two corner seeds alone would give
// it a single output edge.
std::vector<bool> digon_sides(const Features& f) {
  std::map<std::pair<Index, Index>, std::size_t> joining;
  auto ends = [&](std::size_t c) {
    const auto& v = f.curves[c].vertices;
    return std::minmax(v.front(), v.back());
  };
  for (std::size_t c = 0; c < f.curves.size(); ++c)
    if (!f.curves[c].closed) ++joining[ends(c)];
  std::vector<bool> result(f.curves.size());
  for (std::size_t c = 0; c < f.curves.size(); ++c) {
    const auto [a, b] = ends(c);
    result[c] = !f.curves[c].closed && a != b && joining[{a, b}] > 1;
  }
  return result;
}

// How many seeds go inside curve c (its corners not counted). Every loop of curves gets at
// least 3 seeds, so that it stays a loop of output edges however short it is.
std::size_t seeds_inside(const CurveProjector& curves, const Features& f, std::size_t c,
                         bool digon_side, const CurveSpacing& spacing) {
  const auto n = static_cast<std::size_t>(
      std::llround(spacing.length(c, 0, curves.length(c)) / spacing.spacing()));
  if (curves.closed(c)) return std::max<std::size_t>(n, 3);
  const auto& v = f.curves[c].vertices;
  if (v.front() == v.back()) return std::max<std::size_t>(n, 3) - 1;  // a loop through a corner
  const std::size_t inside = n > 0 ? n - 1 : 0;
  return digon_side ? std::max<std::size_t>(inside, 1) : inside;
}

// Whether a seed at the middle of `link`'s stretch would make both halves edges of the
// restricted Delaunay triangulation: each half's middle is nearer to its two ends than to any
// other seed, so the bisector of the ends meets the curve inside both their cells (the curve's
// own Gabriel condition).
bool halves_witnessed(const std::vector<Vec3>& seeds, const PointTree& tree,
                      const std::vector<Vec3>& added, const FeatureLink& link,
                      const CurveProjector& curves) {
  const double middle = (link.from + link.to) / 2;
  const Vec3 split = curves.at(link.curve, middle);
  std::vector<Index> nearer;
  auto witnessed = [&](const Vec3& end, double from, double to) {
    const Vec3 q = curves.at(link.curve, (from + to) / 2);
    const double r2 = std::min(dot(q - end, q - end), dot(q - split, q - split));
    tree.within(q, r2 * (1 - 1e-9), nearer);
    return std::all_of(nearer.begin(), nearer.end(),
                       [&](Index s) { return s == link.seeds[0] || s == link.seeds[1]; }) &&
           std::none_of(added.begin(), added.end(),
                        [&](const Vec3& p) { return dot(q - p, q - p) < r2 * (1 - 1e-9); });
  };
  const Vec3& first = seeds[link.seeds[0]];
  const Vec3& second = seeds[link.seeds[1]];
  // Which seed sits at `from`: the one nearer to that end of the stretch.
  const Vec3 at_from = curves.at(link.curve, link.from);
  const bool first_at_from =
      dot(first - at_from, first - at_from) <= dot(second - at_from, second - at_from);
  return witnessed(first_at_from ? first : second, link.from, middle) &&
         witnessed(first_at_from ? second : first, middle, link.to);
}

}  // namespace

SeedConstraints place_feature_seeds(std::vector<Vec3>& seeds, const TriangleMesh& mesh,
                                    const Features& features, const CurveProjector& curves,
                                    const CurveSpacing& spacing) {
  struct Wanted {
    Vec3 point;
    SeedConstraints::Kind kind;
    std::uint32_t curve;
  };
  std::vector<Wanted> wanted;
  for (Index v : features.corners)
    wanted.push_back({mesh.vertices[v], SeedConstraints::Kind::corner, 0});
  const std::vector<bool> digon = digon_sides(features);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const std::size_t n = seeds_inside(curves, features, c, digon[c], spacing);
    // Evenly spaced by measured length; a loop's seeds start half a step from its first vertex.
    const double step =
        spacing.length(c, 0, curves.length(c)) / static_cast<double>(curves.closed(c) ? n : n + 1);
    for (std::size_t k = 0; k < n; ++k) {
      const double u = curves.closed(c) ? (static_cast<double>(k) + 0.5) * step
                                        : static_cast<double>(k + 1) * step;
      wanted.push_back({curves.at(c, spacing.arclength(c, u)), SeedConstraints::Kind::curve,
                        static_cast<std::uint32_t>(c)});
    }
  }
  // A point wanted twice (curves that overlap in space; corners at one point, as the two copies
  // of a vertex that repair kept apart) gets one seed: seeds must be distinct. Each corner still
  // names its seed, in the order of Features::corners.
  std::set<Vec3> points;
  for (const Wanted& w : wanted) points.insert(w.point);
  const std::size_t distinct = points.size();
  if (distinct >= seeds.size())
    throw FeaturesNeedMoreSeeds(
        "the sharp features need " + std::to_string(distinct) +
            " vertices on their own, and the output has " + std::to_string(seeds.size()) +
            ": ask for more vertices, a larger feature angle, or no features",
        distinct);

  SeedConstraints result;
  result.kind.assign(seeds.size(), SeedConstraints::Kind::surface);
  result.curve.assign(seeds.size(), 0);
  result.anchor.assign(seeds.size(), {});
  const PointTree tree(seeds);
  std::vector<bool> taken(seeds.size(), false);
  std::vector<Index> near;
  std::map<Vec3, Index> placed;  // wanted points, and the seed each got
  for (const Wanted& w : wanted) {
    if (const auto at = placed.find(w.point); at != placed.end()) {
      if (w.kind == SeedConstraints::Kind::corner) result.corner_seed.push_back(at->second);
      continue;
    }
    // The nearest seed not taken: widen the search until one turns up (it must: fewer wanted
    // points than seeds).
    Index chosen = 0;
    for (std::size_t k = 8;; k *= 4) {
      tree.nearest(w.point, k, near);
      std::sort(near.begin(), near.end(), [&](Index a, Index b) {
        const double da = dot(seeds[a] - w.point, seeds[a] - w.point);
        const double db = dot(seeds[b] - w.point, seeds[b] - w.point);
        return da < db || (da == db && a < b);
      });
      const auto free = std::find_if(near.begin(), near.end(), [&](Index s) { return !taken[s]; });
      if (free != near.end()) {
        chosen = *free;
        break;
      }
    }
    taken[chosen] = true;
    placed.emplace(w.point, chosen);
    seeds[chosen] = w.point;
    result.kind[chosen] = w.kind;
    result.curve[chosen] = w.curve;
    result.anchor[chosen] = w.point;
    if (w.kind == SeedConstraints::Kind::corner) result.corner_seed.push_back(chosen);
  }
  return result;
}

std::size_t feature_seed_count(const Features& features, const CurveProjector& curves,
                               const CurveSpacing& spacing) {
  const std::vector<bool> digon = digon_sides(features);
  std::size_t count = features.corners.size();
  for (std::size_t c = 0; c < curves.size(); ++c)
    count += seeds_inside(curves, features, c, digon[c], spacing);
  return count;
}

std::size_t snap_stray_seeds(std::vector<Vec3>& seeds, SeedConstraints& c,
                             const CurveProjector& curves, const CurveSpacing& spacing) {
  const PointTree tree(seeds);
  constexpr auto kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> joins(seeds.size(), kNone);  // per stray seed: the curve it joins
  std::vector<double> d2(seeds.size(), std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const double length = spacing.length(k, 0, curves.length(k));
    const auto n = static_cast<std::size_t>(std::ceil(8 * length / spacing.spacing())) + 1;
    for (std::size_t i = 0; i <= n; ++i) {
      const Vec3 p = curves.at(
          k, spacing.arclength(k, length * static_cast<double>(i) / static_cast<double>(n)));
      const Index s = tree(p);
      const double d = dot(seeds[s] - p, seeds[s] - p);
      if (c.kind[s] == SeedConstraints::Kind::surface && d < d2[s])
        d2[s] = d, joins[s] = static_cast<std::uint32_t>(k);
    }
  }
  std::set<Vec3> occupied(seeds.begin(), seeds.end());
  std::size_t snapped = 0;
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    if (joins[s] == kNone) continue;
    const Vec3 p = curves.nearest(joins[s], seeds[s]).point;
    if (!occupied.insert(p).second) continue;  // seeds stay distinct
    seeds[s] = p;
    c.kind[s] = SeedConstraints::Kind::curve;
    c.curve[s] = joins[s];
    ++snapped;
  }
  return snapped;
}

SeedsAlongCurves seeds_along_curves(const std::vector<Vec3>& seeds, const SeedConstraints& c,
                                    const CurveProjector& curves) {
  SeedsAlongCurves along(curves.size());
  for (Index s = 0; s < seeds.size(); ++s)
    if (c.kind[s] == SeedConstraints::Kind::curve)
      along[c.curve[s]].push_back({curves.nearest(c.curve[s], seeds[s]).arclength, s});
  for (auto& on : along) std::sort(on.begin(), on.end());
  return along;
}

std::vector<FeatureLink> feature_links(const std::vector<Vec3>& seeds, const SeedConstraints& c,
                                       const Features& features, const CurveProjector& curves) {
  SeedsAlongCurves along = seeds_along_curves(seeds, c, curves);
  auto corner_seed = [&](Index vertex) {
    const auto at = std::lower_bound(features.corners.begin(), features.corners.end(), vertex);
    return c.corner_seed[static_cast<std::size_t>(at - features.corners.begin())];
  };
  std::vector<FeatureLink> links;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const bool closed = curves.closed(k);
    const auto& v = features.curves[k].vertices;
    if (!closed) {
      along[k].insert(along[k].begin(), {0.0, corner_seed(v.front())});
      along[k].push_back({curves.length(k), corner_seed(v.back())});
    }
    const auto curve = static_cast<std::uint32_t>(k);
    auto link = [&](const std::pair<double, Index>& a, const std::pair<double, Index>& b,
                    double wrap) {
      links.push_back({{std::min(a.second, b.second), std::max(a.second, b.second)},
                       curve,
                       a.first,
                       b.first + wrap});
    };
    for (std::size_t i = 0; i + 1 < along[k].size(); ++i) link(along[k][i], along[k][i + 1], 0);
    if (closed && along[k].size() > 2) link(along[k].back(), along[k].front(), curves.length(k));
  }
  return links;
}

std::size_t mend_missing_links(std::vector<Vec3>& seeds, SeedConstraints& c,
                               const std::vector<FeatureLink>& missing,
                               const CurveProjector& curves, const CurveSpacing& spacing) {
  if (missing.empty()) return 0;
  const std::vector<Vec3> before = seeds;  // owners are judged on the seeds before any move
  const PointTree tree(before);
  // Where seeds are: sorted, and the middles taken since in a set (a set of every seed took
  // over 100 bytes a seed: 53 MB for igea.ply at 500k).
  std::vector<Vec3> occupied = seeds;
  std::sort(occupied.begin(), occupied.end());
  std::set<Vec3> taken;
  std::vector<bool> moved(seeds.size(), false);
  std::vector<Vec3> added;  // the new seeds, not in the tree
  std::size_t mended = 0;
  for (const FeatureLink& link : missing) {
    // The stretch's stray owners, by samples an eighth of a spacing apart: surface seeds
    // nearest to one of its points. The one nearest to the stretch's middle joins the curve there.
    const Vec3 middle = curves.at(link.curve, (link.from + link.to) / 2);
    const double length = spacing.length(link.curve, link.from, link.to);
    const auto n = static_cast<std::size_t>(std::ceil(8 * length / spacing.spacing())) + 1;
    Index stray = kNoIndex;
    double stray_d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < n; ++i) {
      const double s =
          link.from + (link.to - link.from) * static_cast<double>(i) / static_cast<double>(n);
      const Index owner = tree(curves.at(link.curve, s));
      if (moved[owner] || c.kind[owner] != SeedConstraints::Kind::surface) continue;
      const double d2 = dot(before[owner] - middle, before[owner] - middle);
      if (d2 < stray_d2) stray_d2 = d2, stray = owner;
    }
    // No surface seed to take: feature seeds of other curves cut the stretch, as in a narrow
    // wedge between two curves or a saw of corners finer than the spacing. A new seed splits
    // the link in two where both halves would then be traced for sure, and are at least 0.45
    // spacings long; elsewhere the seeds it would crowd there could squeeze corner cells
    // out of the output (and topology control keeps its best round should one still do).
    const bool add = stray == kNoIndex;
    if (add && (length < kShortestSplitLink * spacing.spacing() ||
                !halves_witnessed(before, tree, added, link, curves)))
      continue;
    if (std::binary_search(occupied.begin(), occupied.end(), middle) ||
        !taken.insert(middle).second)
      continue;  // seeds stay distinct
    if (add) {
      stray = static_cast<Index>(seeds.size());
      seeds.push_back(middle);
      added.push_back(middle);
      moved.push_back(false);
      c.append(SeedConstraints::Kind::curve);
    }
    seeds[stray] = middle;
    moved[stray] = true;
    c.kind[stray] = SeedConstraints::Kind::curve;
    c.curve[stray] = link.curve;
    ++mended;
  }
  return mended;
}

}  // namespace cvtmesh
