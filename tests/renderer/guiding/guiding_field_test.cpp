#include "renderer/guiding/guiding_field.h"

#include <gtest/gtest.h>

#include <random>

namespace landsim::renderer {
namespace {

// Records over a 100 m square: light from the east (+x) on its western half, from straight
// above on its eastern half.
std::vector<GuideRecord> two_halves(int n) {
  std::mt19937 gen(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<GuideRecord> out;
  for (int k = 0; k < n; ++k) {
    const Vec3f p{100.0f * u(gen), 100.0f * u(gen), u(gen)};
    const Vec3f d = square_to_direction(u(gen), u(gen));
    const Vec3f light = p.x < 50.0f ? Vec3f{1.0f, 0.0f, 0.0f} : Vec3f{0.0f, 0.0f, 1.0f};
    out.push_back({p, d, std::pow(std::max(0.0f, dot(d, light)), 16.0f)});
  }
  return out;
}

TEST(GuidingField, EachRegionLearnsItsOwnLight) {
  const GuidingField field(two_halves(40000));
  // 40,000 records split into regions of at most kRecordsPerRegion.
  EXPECT_GE(field.region_count(), 40000 / GuidingField::kRecordsPerRegion);
  const Vec3f east{1.0f, 0.0f, 0.0f}, up{0.0f, 0.0f, 1.0f};
  const DirectionalTree* west = field.at({20.0f, 30.0f, 0.5f});
  const DirectionalTree* eastern = field.at({80.0f, 70.0f, 0.5f});
  ASSERT_NE(west, nullptr);
  ASSERT_NE(eastern, nullptr);
  EXPECT_GT(west->pdf(east), 20.0f * west->pdf(up));
  EXPECT_GT(eastern->pdf(up), 20.0f * eastern->pdf(east));
  // A point beyond the records' box takes the nearest region.
  const DirectionalTree* beyond = field.at({-500.0f, 30.0f, 0.5f});
  ASSERT_NE(beyond, nullptr);
  EXPECT_GT(beyond->pdf(east), 20.0f * beyond->pdf(up));
}

TEST(GuidingField, TooFewRecordsLearnNothing) {
  EXPECT_EQ(GuidingField(std::vector<GuideRecord>{}).at({0.0f, 0.0f, 0.0f}), nullptr);
  EXPECT_EQ(GuidingField(two_halves(static_cast<int>(GuidingField::kLeastRecords) - 1))
                .at({50.0f, 50.0f, 0.5f}),
            nullptr);
  EXPECT_NE(GuidingField(two_halves(static_cast<int>(GuidingField::kLeastRecords) * 4))
                .at({50.0f, 50.0f, 0.5f}),
            nullptr);
}

// The field depends on the records alone: built twice from the same records, the same
// regions and the same densities to the bit.
TEST(GuidingField, TheSameRecordsBuildTheSameField) {
  const GuidingField a(two_halves(20000)), b(two_halves(20000));
  EXPECT_EQ(a.region_count(), b.region_count());
  EXPECT_EQ(a.directional_nodes(), b.directional_nodes());
  const Vec3f d = normalize(Vec3f{0.3f, 0.1f, 0.9f});
  EXPECT_EQ(a.at({10.0f, 90.0f, 0.2f})->pdf(d), b.at({10.0f, 90.0f, 0.2f})->pdf(d));
}

}  // namespace
}  // namespace landsim::renderer
