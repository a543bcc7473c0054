// SelectAutoSources / ComputeDepthRange(s) (declared in patch_match_config.h)
// on constructed models with known overlaps, angles and depths.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "io/patch_match_config.h"
#include "tests/support/sparse_models.h"

namespace msp {
namespace {

using test::ImageAt;
using test::PointAt;

// Adds `count` points near the origin observed by all `image_ids`.
void AddSharedPoints(const std::vector<uint32_t>& image_ids, int count, SparseModel* model) {
  for (int i = 0; i < count; ++i) {
    model->points3D.push_back(
        PointAt(model->points3D.size(), 0.01 * i, -0.02 * i, 0.03 * i, image_ids));
  }
}

// Reference 0 at distance 10 from the points; other images offset sideways
// by a baseline b see the points at an angle of about atan(b / 10).
SparseModel OverlapModel() {
  SparseModel model;
  model.cameras = {test::MakeSparseCamera(1, kSimplePinhole, 100, 100, {100, 50, 50})};
  model.images = {
      ImageAt(100, 0, 0, -10),     // 0: reference
      ImageAt(101, 1, 0, -10),     // 1: ~5.7 deg, 5 shared points
      ImageAt(102, 3, 0, -10),     // 2: ~16.7 deg, 8 shared points
      ImageAt(103, 0.01, 0, -10),  // 3: ~0.06 deg, 10 shared points
      ImageAt(104, -3, 0, -10),    // 4: ~16.7 deg, 8 shared points (ties with 2)
      ImageAt(105, 0, 5, -10),     // 5: shares nothing with the reference
  };
  AddSharedPoints({100, 101}, 5, &model);
  AddSharedPoints({100, 102, 104}, 8, &model);
  AddSharedPoints({100, 103}, 10, &model);
  AddSharedPoints({101, 105}, 20, &model);
  return model;
}

TEST(SourceSelection, RanksBySharedPointsAfterTheAngleFilter) {
  const SparseModel model = OverlapModel();
  // Image 3 shares the most points but its baseline is too narrow for 1 deg;
  // 2 and 4 tie on 8 shared points: the lower model index comes first.
  EXPECT_EQ(SelectAutoSources(model, 0, 20, 1.0), (std::vector<int>{2, 4, 1}));
  EXPECT_EQ(SelectAutoSources(model, 0, 2, 1.0), (std::vector<int>{2, 4}));
  EXPECT_EQ(SelectAutoSources(model, 0, 0, 1.0), (std::vector<int>{}));
}

TEST(SourceSelection, AngleThreshold) {
  const SparseModel model = OverlapModel();
  EXPECT_EQ(SelectAutoSources(model, 0, 20, 0.0), (std::vector<int>{3, 2, 4, 1}));
  EXPECT_EQ(SelectAutoSources(model, 0, 20, 10.0), (std::vector<int>{2, 4}));
  EXPECT_EQ(SelectAutoSources(model, 0, 20, 20.0), (std::vector<int>{}));
}

TEST(SourceSelection, UsesThe75thPercentileAngle) {
  SparseModel model = OverlapModel();
  model.points3D.clear();
  // Image 2 sees 4 points with the reference: the far ones (z = 1000) give
  // ~0.17 deg, the near ones ~16.7 deg. Sorted angles [far, far, near, near]:
  // the 75th percentile is element round(0.75 * 3) = 2, a near one.
  AddSharedPoints({100, 102}, 2, &model);
  for (int i = 0; i < 2; ++i)
    model.points3D.push_back(PointAt(100 + i, 0, 0, 1000.0 + i, {100, 102}));
  EXPECT_EQ(SelectAutoSources(model, 0, 5, 5.0), (std::vector<int>{2}));
  // With six far points, element round(0.75 * 7) = 5 of 8 is a far one.
  for (int i = 0; i < 4; ++i)
    model.points3D.push_back(PointAt(200 + i, 0, 0, 1002.0 + i, {100, 102}));
  EXPECT_EQ(SelectAutoSources(model, 0, 5, 5.0), (std::vector<int>{}));
}

// COLMAP counts every pair of track elements of distinct images, so a track
// listing an image three times shares three points with the reference, and
// each such pair's angle counts in the percentile.
TEST(SourceSelection, ATrackRepeatingAnImageCountsEveryElementPair) {
  SparseModel model = OverlapModel();
  model.points3D.clear();
  AddSharedPoints({100, 102}, 2, &model);
  model.points3D.push_back(PointAt(50, 0, 0, 0, {100, 101, 101, 101}));
  EXPECT_EQ(SelectAutoSources(model, 0, 5, 1.0), (std::vector<int>{1, 2}));

  // Four far points (~0.17 deg) and one near point (~16.7 deg) listed with
  // image 2 four times: of the 8 angles the 75th percentile (element 5) is a
  // near one; counted once per point it would be element 3 of 5, a far one.
  model.points3D.clear();
  for (int i = 0; i < 4; ++i) {
    model.points3D.push_back(PointAt(100 + i, 0, 0, 1000.0 + i, {100, 102}));
  }
  model.points3D.push_back(PointAt(200, 0, 0, 0, {100, 102, 102, 102, 102}));
  EXPECT_EQ(SelectAutoSources(model, 0, 5, 5.0), (std::vector<int>{2}));
}

TEST(SourceSelection, BatchMatchesSingle) {
  const SparseModel model = OverlapModel();
  const std::vector<std::vector<int>> batch =
      SelectAutoSourcesBatch(model, {20, 20, 0, 1, 20, 20}, 1.0);
  ASSERT_EQ(batch.size(), model.images.size());
  EXPECT_EQ(batch[0], SelectAutoSources(model, 0, 20, 1.0));
  EXPECT_EQ(batch[1], SelectAutoSources(model, 1, 20, 1.0));
  EXPECT_TRUE(batch[2].empty());  // not requested
  EXPECT_EQ(batch[3], SelectAutoSources(model, 3, 1, 1.0));
  EXPECT_EQ(batch[4], (std::vector<int>{0, 2}));  // 8 shared points each
  EXPECT_EQ(batch[5], (std::vector<int>{1}));
}

TEST(DepthRange, PercentilesOfObservedDepths) {
  SparseModel model;
  model.images = {ImageAt(1, 0, 0, 0), ImageAt(2, 0, 0, -100), ImageAt(3, 0, 0, 0)};
  // Image 1 observes z = 1..200, plus points behind it that must be ignored.
  for (int z = 200; z >= 1; --z) {
    // Off-axis: the depth is z, not the distance.
    model.points3D.push_back(PointAt(z, 0.5 * z, 0, z, {1, 2}));
  }
  for (int i = 0; i < 50; ++i) model.points3D.push_back(PointAt(1000 + i, 0, 0, -5.0 - i, {1}));
  // A point no track of image 1 contains does not count, however near.
  model.points3D.push_back(PointAt(5000, 0, 0, 0.001, {2}));

  // 200 depths 1..200: indices 200*0.01 = 2 and 200*0.99 = 198 -> 3 and 199.
  const auto range = ComputeDepthRange(model, 0);
  EXPECT_FLOAT_EQ(range.first, 3.0f * 0.75f);
  EXPECT_FLOAT_EQ(range.second, 199.0f * 1.25f);
  // Image 2 sits 100 behind: 201 depths 100.001, 101..300; indices
  // 201*0.01 -> 2 and 201*0.99 -> 198, i.e. 102 and 298.
  const auto range2 = ComputeDepthRange(model, 1);
  EXPECT_FLOAT_EQ(range2.first, 102.0f * 0.75f);
  EXPECT_FLOAT_EQ(range2.second, 298.0f * 1.25f);
  // No observations at all.
  const auto none = ComputeDepthRange(model, 2);
  EXPECT_EQ(none.first, -1.0);
  EXPECT_EQ(none.second, -1.0);
  EXPECT_EQ(ComputeDepthRanges(model)[0], range);
}

TEST(DepthRange, SmallCountsUseTheFirstAndLastIndices) {
  SparseModel model;
  model.images = {ImageAt(1, 0, 0, 0)};
  for (int z : {4, 2, 8}) model.points3D.push_back(PointAt(z, 0, 0, z, {1}));
  // 3 * 0.01 -> 0 and 3 * 0.99 -> 2.
  const auto range = ComputeDepthRange(model, 0);
  EXPECT_FLOAT_EQ(range.first, 2.0f * 0.75f);
  EXPECT_FLOAT_EQ(range.second, 8.0f * 1.25f);
}

// Shared ranges: the reference (image 1, 100x100 px, f = 100, looking down +z
// from the origin) has its own points at z = 10..19; its source (image 2)
// adds points at z = 2 and z = 40 that the reference sees, and one outside
// the reference's image and one behind it, which do not count.
TEST(DepthRange, SharedRangeTakesTheSourcesPointsTheReferenceSees) {
  SparseModel model;
  model.cameras = {test::MakeSparseCamera(1, kPinhole, 100, 100, {100, 100, 50, 50})};
  model.images = {ImageAt(1, 0, 0, 0), ImageAt(2, 1, 0, 0), ImageAt(3, 0, 0, 0)};
  for (int z = 10; z < 20; ++z) model.points3D.push_back(PointAt(z, 0, 0, z, {1}));
  model.points3D.push_back(PointAt(100, 0, 0, 2, {2}));
  model.points3D.push_back(PointAt(101, 0.1, 0, 40, {2, 3}));
  model.points3D.push_back(PointAt(102, 30, 0, 10, {2}));  // u = 350: outside
  model.points3D.push_back(PointAt(103, 0, 0, -4, {2}));   // behind
  model.points3D.push_back(PointAt(104, 0, 0, 1, {3}));    // not a view of the problem
  Problem problem;
  problem.ref = 0;
  problem.srcs = {1};
  Problem alone;
  alone.ref = 0;
  const auto ranges = ComputeSharedDepthRanges(model, {problem, alone});
  // 12 depths 2, 10..19, 40: indices 0 and 11.
  EXPECT_FLOAT_EQ(ranges[0].first, 2.0f * 0.75f);
  EXPECT_FLOAT_EQ(ranges[0].second, 40.0f * 1.25f);
  // Without sources: the reference's own observations, as ComputeDepthRange.
  EXPECT_EQ(ranges[1], ComputeDepthRange(model, 0));
}

}  // namespace
}  // namespace msp
