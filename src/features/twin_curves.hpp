// Twin creases (issue 18 item 5): two feature curves that join the same two corners and run
// within half an output edge length of each other along their whole length. Edges of that
// length cannot trace both without slivers between them, and at that scale they are one
// crease: on organic models they are the sides of a sliver input triangle or a thin strip
// whose edges all fold (cow.off, hand.off, triceratops.off, bones.off: θmin 2-8° at 5k
// vertices, against 21-38° without features).
#pragma once

#include <vector>

#include "cvtmesh/features.hpp"

namespace cvtmesh {

// Per curve of `curves` (`lengths`: theirs): whether it goes as the twin of another. Only curves
// flagged in `droppable` go; of two droppable twins, the longer (on a tie, the later one).
std::vector<bool> twin_curves(const TriangleMesh& mesh, const std::vector<FeatureCurve>& curves,
                              const std::vector<double>& lengths,
                              const std::vector<bool>& droppable, double scale);

}  // namespace cvtmesh
