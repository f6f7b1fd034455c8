// paper §9: presets as bases a scene overrides.
#include <gtest/gtest.h>

#include "src/errors.h"
#include "src/presets.h"
#include "src/scene_file.h"

namespace sandpic {
namespace {

TEST(Presets, EveryPresetIsAValidSceneFollowingSection9) {
  ASSERT_EQ(presets().size(), 4u);
  for (const Preset& p : presets()) {
    Scene s;
    apply_json(s, json::parse(R"({"preset": ")" + p.name + R"("})"));
    EXPECT_EQ(s.preset, p.name);
    EXPECT_NO_THROW(validate(s)) << p.name;
  }
  // §9: mountains large ellipses of small eccentricity; desert and sea small ones of large eccentricity.
  auto with = [](const char* name) {
    Scene s;
    apply_setting(s, std::string("preset=") + name);
    return s;
  };
  EXPECT_GT(with("mountains").segment.semi_major_max, with("desert").segment.semi_major_max);
  EXPECT_LT(with("mountains").segment.eccentricity_max, with("desert").segment.eccentricity_min);
  EXPECT_LT(with("mountains").segment.eccentricity_max, with("sea").segment.eccentricity_min);
  EXPECT_GT(with("clouds").init.dominant_share, with("mountains").init.dominant_share);
}

TEST(Presets, TheScenesOwnKeysOverrideThePresetWhateverTheirOrder) {
  Scene s;
  // "grains" and "init" sort before "preset": they must still win.
  apply_json(s, json::parse(R"({"init": {"dominant_share": 0.5}, "preset": "clouds",
                               "segment": {"semi_major_max": 50}})"));
  EXPECT_EQ(s.init.dominant_share, 0.5);
  EXPECT_EQ(s.segment.semi_major_max, 50);
  EXPECT_EQ(s.segment.semi_major_min, 14);  // the preset's
  Scene t;
  try {
    apply_json(t, json::parse(R"({"preset": "mountain"})"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'preset'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("mountains"), std::string::npos);  // lists the names
  }
}

}  // namespace
}  // namespace sandpic
