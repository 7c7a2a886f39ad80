// The control of the output's halving rounds (finish_output): which round goes on from which,
// which is kept, and when they end, apart from what a round does, so that it can be tested on
// rounds made up.
#pragma once

#include <optional>
#include <utility>

#include "finish/bar_shapes.hpp"

namespace cvtmesh {

// At most `rounds` rounds from `start`, shaped `start_shapes`; returns the best round. Each is
// tried from the last one gone on from, `attempt(from, k, again)` giving the round and its
// shapes, or nothing where round k has nothing to do (then the rounds end), and judged against
// the best so far, `judge(shapes, best_shapes)`. A better round is kept and gone on from; a mixed
// one (better in one part, worse in another) is not kept but gone on from, as it can open the way
// for the next (lion.off at 10k: its first round takes the worst away from its 8° tip from 0.55
// to 0.40 while bettering the tip, its next two to 0.62); one better nowhere is tried once more
// another way, `attempt(from, k, true)` (nothing: there is none), the better verdict of the two
// taken, and ends the rounds if it is still better nowhere (conrod.stl of MeshLab's samples,
// non-manifold, at 5k: three such rounds of 0.6 s each, twice).
template <class Round, class Shapes, class Attempt, class Judge>
Round best_round(Round start, Shapes start_shapes, int rounds, const Attempt& attempt,
                 const Judge& judge) {
  Round current = start;
  Round best = std::move(start);
  Shapes best_shapes = std::move(start_shapes);
  for (int k = 0; k < rounds; ++k) {
    std::optional<std::pair<Round, Shapes>> tried = attempt(current, k, false);
    if (!tried) break;
    Verdict verdict = judge(tried->second, best_shapes);
    if (verdict == Verdict::no_better) {
      std::optional<std::pair<Round, Shapes>> other = attempt(current, k, true);
      if (other) {
        const Verdict other_verdict = judge(other->second, best_shapes);
        if (other_verdict < verdict) {
          tried = std::move(other);
          verdict = other_verdict;
        }
      }
    }
    if (verdict == Verdict::no_better) break;
    current = std::move(tried->first);
    if (verdict == Verdict::better) {
      best = current;
      best_shapes = std::move(tried->second);
    }
  }
  return best;
}

}  // namespace cvtmesh
