// The control of the halving rounds (finish/best_round) on rounds made up: each round is a
// number, its shapes the verdict a script gives it, and the attempts made are recorded.
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "finish/best_round.hpp"

namespace cvtmesh {
namespace {

// A round is named by the round it came from and how: from * 10 + (again ? 2 : 1), so that the
// path taken can be read off the result. The script gives each attempt's verdict (keyed by the
// round tried from, the round index and `again`), or none for an attempt with nothing to do.
struct Script {
  std::map<std::tuple<int, int, bool>, std::optional<Verdict>> verdicts;
  std::vector<std::tuple<int, int, bool>> made;  // the attempts, in order

  auto attempt() {
    return [this](const int& from, int k, bool again) -> std::optional<std::pair<int, Verdict>> {
      made.emplace_back(from, k, again);
      const auto it = verdicts.find({from, k, again});
      if (it == verdicts.end() || !it->second) return std::nullopt;
      return std::pair{from * 10 + (again ? 2 : 1), *it->second};
    };
  }
};

// The round best_round keeps, from round 0 (as bad as can be), in at most `rounds` rounds.
int best_of(Script& s, int rounds) {
  return best_round(0, Verdict::no_better, rounds, s.attempt(),
                    [](Verdict v, Verdict) { return v; });
}

TEST(BestRound, KeepsTheBestRoundNotTheLast) {
  Script s;
  s.verdicts = {{{0, 0, false}, Verdict::better},
                {{1, 1, false}, Verdict::mixed},
                {{11, 2, false}, Verdict::mixed}};
  EXPECT_EQ(best_of(s, 3), 1);
  // The mixed rounds were gone on from: round 2 from round 1's result.
  EXPECT_EQ(s.made.back(), std::tuple(11, 2, false));
}

TEST(BestRound, GoesOnFromAMixedRoundAndKeepsWhatIsBetterAfterIt) {
  Script s;
  s.verdicts = {{{0, 0, false}, Verdict::mixed}, {{1, 1, false}, Verdict::better}};
  EXPECT_EQ(best_of(s, 3), 11);
}

TEST(BestRound, ARoundBetterNowhereIsTriedAgainAnotherWay) {
  Script s;
  s.verdicts = {{{0, 0, false}, Verdict::no_better},
                {{0, 0, true}, Verdict::better},
                {{2, 1, false}, Verdict::better}};
  EXPECT_EQ(best_of(s, 2), 21);
  EXPECT_EQ(s.made,
            (std::vector<std::tuple<int, int, bool>>{{0, 0, false}, {0, 0, true}, {2, 1, false}}));
}

TEST(BestRound, ARoundBetterNowhereEitherWayEndsTheRounds) {
  Script s;
  s.verdicts = {{{0, 0, false}, Verdict::better},
                {{1, 1, false}, Verdict::no_better},
                {{1, 1, true}, Verdict::no_better},
                {{1, 2, false}, Verdict::better}};
  EXPECT_EQ(best_of(s, 3), 1);
  EXPECT_EQ(s.made.size(), 3u);  // round 2 never tried
}

TEST(BestRound, TheOtherWayIsTakenOnlyWhereItIsBetter) {
  Script s;
  // Better nowhere, and the other way has nothing to do: the rounds end.
  s.verdicts = {{{0, 0, false}, Verdict::no_better}, {{0, 0, true}, std::nullopt}};
  EXPECT_EQ(best_of(s, 3), 0);
  // Mixed rounds are not tried again.
  Script t;
  t.verdicts = {{{0, 0, false}, Verdict::mixed}, {{1, 1, false}, std::nullopt}};
  EXPECT_EQ(best_of(t, 3), 0);
  EXPECT_EQ(t.made, (std::vector<std::tuple<int, int, bool>>{{0, 0, false}, {1, 1, false}}));
}

TEST(BestRound, EndsWhereARoundHasNothingToDoAndAtTheCap) {
  Script s;
  s.verdicts = {{{0, 0, false}, Verdict::better}};
  EXPECT_EQ(best_of(s, 3), 1);
  EXPECT_EQ(s.made.size(), 2u);  // round 1 had nothing to do
  Script t;
  t.verdicts = {{{0, 0, false}, Verdict::better}, {{1, 1, false}, Verdict::better}};
  EXPECT_EQ(best_of(t, 1), 1);
  EXPECT_EQ(t.made.size(), 1u);
}

}  // namespace
}  // namespace cvtmesh
