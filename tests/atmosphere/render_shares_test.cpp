// A reference render split into shares of its pixels, for a cluster: the
// shares' sums put together give the bits of the render made at once, and
// the shares of a run of frames cover it once, in order.
#include "atmosphere/reference/reference_render.h"
#include "core/error.h"
#include "core/share.h"
#include "lab/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "tests/unity_id.h"

namespace planet {
namespace {
namespace PLANET_TEST_ID {

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(RenderSharesTest, SharesOfThePixelsPutTogetherGiveTheSameBits) {
  Scene scene = find_scene("earth_sunset");
  scene.width = 5;  // 15 pixels over 4 shares: uneven on purpose
  scene.height = 3;
  Body body = scene_body(scene);
  AtmosphereModel model = scene_atmosphere(scene, body);
  ReferenceView view = reference_view(scene, body, model);
  Medium medium = make_medium(model, ReferenceMode::kRgb);
  ReferenceSettings settings;
  settings.paths = PathBudget({12, 6, 20});
  settings.seed = scene.seed();
  settings.chunk_paths = 5;
  ReferenceImage at_once = render_reference(medium, view, settings);

  // Each share in its own chunks; its last checkpoint holds its sums.
  const int count = 4;
  std::vector<RenderSums> shares(count);
  for (int k = count - 1; k >= 0; --k) {
    ReferenceSettings share = settings;
    share.share = Share{k, count};
    share.chunk_paths = 3 + k;
    share.checkpoint = [&, k](const RenderSums& sums) { shares[size_t(k)] = sums; };
    ReferenceImage part = render_reference(medium, view, share);
    EXPECT_EQ(part.paths, uint64_t(k < 3 ? 4 : 3) * 38u) << "its own pixels' paths only";
  }
  RenderSums merged = shares[0];
  const size_t lanes = merged.done.size();
  for (size_t pixel = 0; pixel < 15; ++pixel) {
    const RenderSums& from = shares[pixel % count];
    std::copy_n(&from.sum[pixel * lanes], lanes, &merged.sum[pixel * lanes]);
  }
  ReferenceImage put_together;
  resolve_sums(medium, merged, put_together);
  EXPECT_TRUE(same_bits(at_once.rgb, put_together.rgb));
  EXPECT_TRUE(same_bits(at_once.noise, put_together.noise));
}

TEST(RenderSharesTest, SharesOfFramesCoverThemOnceInOrder) {
  for (int total : {1, 5, 41, 1000}) {
    for (int count : {1, 3, 4, 16}) {
      int next = 0;
      for (int k = 0; k < count; ++k) {
        auto [first, end] = share_range(Share{k, count}, total);
        EXPECT_EQ(first, next) << k << "/" << count << " of " << total;
        EXPECT_LE(end - first, total / count + 1);
        next = end;
      }
      EXPECT_EQ(next, total);
    }
  }
}

TEST(RenderSharesTest, ShareIsKOfNFromZero) {
  EXPECT_EQ(parse_share("3/4", "--shard"), (Share{3, 4}));
  EXPECT_EQ(parse_share("0/1", "--shard"), (Share{0, 1}));
  for (const char* bad : {"4/4", "1", "-1/4", "1/0", "a/b", "1/4/2", " 1/4", "1/70000"}) {
    EXPECT_THROW(parse_share(bad, "--shard"), InputError) << bad;
  }
}

}  // namespace PLANET_TEST_ID
}  // namespace
}  // namespace planet
