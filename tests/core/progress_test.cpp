// ProgressPart (core/progress.hpp): a stage's fractions mapped into its slice
// of the caller's progress, clamped to the slice, never decreasing, thinned
// to the step, the slice's end reported once. Worked by hand: the slice
// [0.2, 0.6] maps f to 0.2 + 0.4 f.
#include "casteljau/core/progress.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace casteljau {
namespace {

struct Heard {
  std::vector<double> fractions;
  Progress progress() {
    return Progress{[](void* self, double f) { static_cast<Heard*>(self)->fractions.push_back(f); }, this};
  }
};

TEST(ProgressPart, MapsClampsThinsAndEndsOnce) {
  Heard heard;
  ProgressPart stage(heard.progress(), 0.2, 0.6, 0.1);
  stage(0.0);    // 0.2: where the stage starts, the first report
  stage(0.5);    // 0.4
  stage(0.6);    // 0.44: closer than the step to 0.4, dropped
  stage(0.25);   // 0.3: backwards (a stage done again), dropped
  stage(-3.0);   // below the slice: 0.2, dropped
  stage(0.8);    // 0.52
  stage(7.0);    // beyond the slice: its end, 0.6
  stage.finish();  // the end again: reported once only
  ASSERT_EQ(heard.fractions.size(), 4u);
  EXPECT_EQ(heard.fractions[0], 0.2);
  EXPECT_DOUBLE_EQ(heard.fractions[1], 0.4);
  EXPECT_DOUBLE_EQ(heard.fractions[2], 0.52);
  EXPECT_EQ(heard.fractions[3], 0.6);
}

TEST(ProgressPart, SubStagesAreClampedToTheirShare) {
  Heard heard;
  ProgressPart stage(heard.progress(), 0.0, 1.0);
  stage(0.5, 1.0, 0.5);   // halfway through the second half: 0.75
  stage(0.5, 1.0, -1.0);  // before its sub-stage: 0.5, below what was reported
  stage(0.5, 1.0, 2.0);   // past it: its end, 1
  ASSERT_EQ(heard.fractions.size(), 2u);
  EXPECT_EQ(heard.fractions[0], 0.75);
  EXPECT_EQ(heard.fractions[1], 1.0);
  // A default Progress hears nothing and does not fail.
  ProgressPart silent(Progress{}, 0.0, 1.0);
  silent(0.5);
  silent.finish();
}

}  // namespace
}  // namespace casteljau
