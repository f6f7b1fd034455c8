// paper §9: "large ellipses of smaller eccentricities to generate mountains
// and smaller ellipses of large eccentricities to generate scenes like sea
// surfaces and deserts"; cells smaller than the ellipses give strata, and the
// colours of a cell's grains set the contrast of the textures.
#include "src/presets.h"

namespace sandpic {

const std::vector<Preset>& presets() {
  static const std::vector<Preset> all = {
      {"mountains",
       "large ellipses of small eccentricity (steep piles) over smaller cells of strong contrast; Fig. 14's colours",
       R"({"init": {"method": "tessellation", "tessellation": "varying", "row_height_min": 10, "row_height_max": 40,
            "cell_width_min": 30, "cell_width_max": 120, "dominant_share": 0.8},
            "segment": {"method": "ellipses", "semi_major_min": 60, "semi_major_max": 170,
            "eccentricity_min": 0.45, "eccentricity_max": 0.6},
            "grains": {"colors": ["#333738", "#626669", "#5abe78", "#bec6c8"]}})"},
      {"desert",
       "small ellipses of large eccentricity (flat dunes) over thin cells; Fig. 16's colours",
       R"({"init": {"method": "tessellation", "tessellation": "varying", "row_height_min": 6, "row_height_max": 22,
            "cell_width_min": 20, "cell_width_max": 90, "dominant_share": 0.8},
            "segment": {"method": "ellipses", "semi_major_min": 22, "semi_major_max": 60,
            "eccentricity_min": 0.88, "eccentricity_max": 0.95},
            "grains": {"colors": ["#1a0c0a", "#641e0a", "#c86414", "#fa8c1e"]}})"},
      {"sea",
       "sea surface: small, very flat ellipses over thin full-width strips of blues",
       R"({"init": {"method": "tessellation", "tessellation": "strips", "row_height_min": 4, "row_height_max": 14,
            "dominant_share": 0.85},
            "segment": {"method": "ellipses", "semi_major_min": 18, "semi_major_max": 45,
            "eccentricity_min": 0.92, "eccentricity_max": 0.97},
            "grains": {"colors": ["#0b2545", "#13598b", "#3e9cc9", "#e8f4f8"]}})"},
      {"clouds",
       "small cells of small colour variation, mostly the light classes, under small ellipses (§10, Fig. 17)",
       R"({"init": {"method": "tessellation", "tessellation": "varying", "row_height_min": 5, "row_height_max": 14,
            "cell_width_min": 12, "cell_width_max": 40, "dominant_share": 0.95},
            "segment": {"method": "ellipses", "semi_major_min": 14, "semi_major_max": 34,
            "eccentricity_min": 0.7, "eccentricity_max": 0.85},
            "grains": {"proportions": [0.04, 0.12, 0.42, 0.42],
            "colors": ["#5d6670", "#9aa3ad", "#d5dbe1", "#fbfcfd"]}})"},
  };
  return all;
}

const Preset* find_preset(const std::string& name) {
  for (const Preset& p : presets())
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace sandpic
