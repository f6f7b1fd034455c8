#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include "src/errors.h"
#include "src/scene_file.h"
#include "tests/test_folder.h"

namespace sandpic {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneFile, DefaultsAreThePapers) {
  Scene s;
  EXPECT_EQ(s.window.width, 1000);
  EXPECT_EQ(s.window.height, 700);
  EXPECT_EQ(s.region.height, 350);
  EXPECT_DOUBLE_EQ(s.grains.density_g_cm3[0], 3.2);
  EXPECT_DOUBLE_EQ(s.grains.diameter_mm[2], 0.1);
  EXPECT_DOUBLE_EQ(s.grains.proportions[0], 0.375);
  EXPECT_DOUBLE_EQ(s.init.dominant_share, 0.8);
  EXPECT_DOUBLE_EQ(s.release.outlet_width_mm, 15);
  EXPECT_DOUBLE_EQ(s.physics.friction, 0.4);
  EXPECT_DOUBLE_EQ(s.physics.restitution, 0.1);
}

TEST(SceneFile, DumpReadsBackToTheSameScene) {
  Scene s;
  s.init.cell_overrides = {{3, 1, 2}};
  s.segment.ellipses = {{10, 20, 30, 15, 12}};
  s.lattice.repose_deg = std::array<double, 4>{20, 25, 30, 35};
  s.layout_seed = 77;
  ordered_json dumped = to_json(s);
  Scene t;
  apply_json(t, json::parse(dumped.dump()));
  EXPECT_EQ(to_json(t).dump(), dumped.dump());
  EXPECT_EQ(t.layout(), 77u);
  EXPECT_EQ(t.physics_rng(), s.seed);
}

TEST(SceneFile, EveryRequiredKeyExists) {
  std::string keys;
  for (const Field& f : scene_fields()) keys += f.path + " ";
  for (const char* k : {"init.method ", "init.image ", "mode ", "seed ", "layout_seed ", "physics_seed "})
    EXPECT_NE(keys.find(k), std::string::npos) << k;
}

TEST(SceneFile, UnknownKeySuggestsTheNearest) {
  Scene s;
  std::string e = error_of([&] { apply_json(s, json::parse(R"({"segment": {"eccentricty_max": 0.5}})")); });
  EXPECT_NE(e.find("'segment.eccentricty_max'"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'segment.eccentricity_max'"), std::string::npos) << e;
  e = error_of([&] { apply_setting(s, "friction=0.2"); });
  EXPECT_NE(e.find("physics.friction"), std::string::npos) << e;
}

TEST(SceneFile, BadValuesNameTheirKey) {
  Scene s;
  EXPECT_NE(error_of([&] { apply_json(s, json::parse(R"({"window": {"width": "wide"}})")); }).find("window.width"),
            std::string::npos);
  EXPECT_NE(error_of([&] { apply_setting(s, "physics.friction=-1"); }).find("physics.friction"), std::string::npos);
  EXPECT_NE(error_of([&] { apply_setting(s, "window.width=10.5"); }).find("whole number"), std::string::npos);
  EXPECT_NE(error_of([&] { apply_setting(s, "mode=fast"); }).find("lattice | dem"), std::string::npos);
  EXPECT_NE(error_of([&] { apply_setting(s, "grains.colors=[1,2,3]"); }).find("grains.colors"), std::string::npos);
  EXPECT_NE(error_of([&] { apply_setting(s, "physics.friction=1e999"); }).find("physics.friction"),
            std::string::npos);
  EXPECT_NE(error_of([&] { apply_setting(s, "mode=l\xffx"); }).find("'mode'"), std::string::npos);  // not UTF-8
  std::string e = error_of([&] { apply_json(s, json::parse(R"({"segment": {"ellipses": [{"cx": 1, "cy": 2}]}})")); });
  EXPECT_NE(e.find("segment.ellipses[0].a"), std::string::npos) << e;
}

TEST(SceneFile, ColoursAreHexOrTriples) {
  Scene s;
  for (const char* bad : {"#-1-1-1", "# 1 2 3", "#12345", "#1234567", "red"})
    EXPECT_NE(error_of([&] { apply_setting(s, std::string("render.background_color=\"") + bad + "\""); })
                  .find("render.background_color"),
              std::string::npos)
        << bad;
  apply_setting(s, R"(grains.colors=["#ff0000", [0, 255, 0], "#0000ff", [1, 2, 3]])");
  EXPECT_EQ(s.grains.colors[0], (Rgb{255, 0, 0}));
  EXPECT_EQ(s.grains.colors[1], (Rgb{0, 255, 0}));
  EXPECT_EQ(s.grains.colors[3], (Rgb{1, 2, 3}));
}

TEST(SceneFile, CrossKeyChecks) {
  Scene s;
  s.region.height = 800;
  EXPECT_NE(error_of([&] { validate(s); }).find("region.height"), std::string::npos);
  s = Scene{};
  s.init.method = InitMethod::Halftone;
  EXPECT_NE(error_of([&] { validate(s); }).find("init.image"), std::string::npos);
  s = Scene{};
  s.region.height = 700;  // the region's sand would not fit in the window
  EXPECT_NE(error_of([&] { validate(s); }).find("would not fit"), std::string::npos);
  s = Scene{};
  s.segment.semi_major_min = s.segment.semi_major_max = 1;  // ellipses thinner than a pixel
  s.segment.eccentricity_min = s.segment.eccentricity_max = 0.999;
  EXPECT_NE(error_of([&] { validate(s); }).find("segment.semi_major_min"), std::string::npos);
  s = Scene{};
  EXPECT_NE(error_of([&] { apply_scale(s, 0.05); }).find("--scale"), std::string::npos);
}

// A scale too small for a key the user never set says which scale works.
TEST(SceneFile, TooSmallAScaleNamesTheSmallestThatWorks) {
  const std::string e = error_of([] {
    Scene s;
    apply_scale(s, 0.05);
  });
  const std::string tag = "the smallest --scale that works for this scene is ";
  ASSERT_NE(e.find(tag), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos);
  const double works = std::stod(e.substr(e.find(tag) + tag.size()));
  Scene ok, below;
  EXPECT_NO_THROW(apply_scale(ok, works));
  EXPECT_THROW(apply_scale(below, works * 0.99), InputError);
  EXPECT_GT(works, 0.05);
  EXPECT_EQ(error_of([&] { validate(Scene{}); }), "");
}

TEST(SceneFile, ScaleMultipliesPixelLengthsAndKeepsGrainSizeInPixels) {
  Scene s;
  s.segment.ellipses = {{100, 50, 40, 20, 30}};
  double area = grain_area_px(s, 0);
  apply_scale(s, 0.25);
  EXPECT_EQ(s.window.width, 250);
  EXPECT_EQ(s.window.height, 175);
  EXPECT_EQ(s.region.height, 88);
  EXPECT_DOUBLE_EQ(s.segment.semi_major_max, 150 * 0.25);
  EXPECT_DOUBLE_EQ(s.segment.ellipses[0].cx, 25);
  EXPECT_DOUBLE_EQ(s.segment.ellipses[0].angle_deg, 30);
  EXPECT_NEAR(grain_area_px(s, 0), area, 1e-12);
  EXPECT_NEAR(s.release.outlet_width_mm * px_per_mm(s), 15 / 0.18 * 0.25, 1e-9);  // the outlet in px scales too
}

TEST(SceneFile, LoadReportsFileAndPosition) {
  std::string path = testing::TempDir() + "/bad_scene.json";
  std::ofstream(path) << "{\n  \"mode\": \"lattice\",\n  \"seed\": ,\n}\n";
  std::string e = error_of([&] { load_scene(path); });
  EXPECT_NE(e.find(path), std::string::npos) << e;
  EXPECT_NE(e.find("line 3"), std::string::npos) << e;
  EXPECT_NE(error_of([&] { load_scene("/no/such/scene.json"); }).find("/no/such/scene.json"), std::string::npos);
  std::remove(path.c_str());
}

// A number past a double's range: nlohmann says neither where nor which key.
TEST(SceneFile, ANumberTooLargeNamesItsKeyAndPosition) {
  std::string path = testing::TempDir() + "/huge_scene.json";
  std::ofstream(path) << "{\n  \"segment\": {\"ellipses\": [{\"cx\": 1, \"cy\": 2, \"a\": 3, \"b\": 4},\n"
                         "    {\"cx\": 1e999}]}\n}\n";
  std::string e = error_of([&] { load_scene(path); });
  EXPECT_NE(e.find("'segment.ellipses[1].cx'"), std::string::npos) << e;
  EXPECT_NE(e.find("line 3"), std::string::npos) << e;
  std::remove(path.c_str());
}

// Found by tests/fuzz's review: nlohmann's parser copies values recursively,
// so a scene nested 100,000 levels deep overflowed the stack (a crash where a
// one-line error is due), in a scene file and in a --set value alike.
TEST(SceneFile, DeepNestingIsAnErrorNotACrash) {
  const size_t n = 100000;
  const std::string deep = std::string(n, '[') + std::string(n, ']');
  std::string e = error_of([&] { scene_from_text("{\"mode\": " + deep + "}", "deep.json", "."); });
  EXPECT_NE(e.find("deep.json"), std::string::npos) << e;
  EXPECT_NE(e.find("nested"), std::string::npos) << e;
  Scene s;
  EXPECT_NE(error_of([&] { apply_setting(s, "mode=" + deep); }).find("nested"), std::string::npos);
  // A real scene's depth is still read.
  s = scene_from_text(R"({"regions": [{"segment": {"sketch": {"ridges": [[[1, 2], [3, 4]]]}}}]})", "ok.json", ".");
  EXPECT_EQ(s.regions.size(), 1u);
}

// Found reviewing validate() for the fuzz target: the "would not fit" message
// printed the sand's area through long(), undefined past 2^63 px² (negative on
// x86), which the largest grains on the finest pixels reach.
TEST(SceneFile, HugeSandAreaIsReportedNotOverflowed) {
  Scene s;
  s.window = {20000, 20000};
  s.region.height = 20000;
  s.units.mm_per_pixel = 1e-4;
  s.grains.diameter_mm = {100, 100, 100, 100};
  std::string e = error_of([&] { validate(s); });
  EXPECT_NE(e.find("would not fit"), std::string::npos) << e;
  EXPECT_NE(e.find("up to 383"), std::string::npos) << e;  // pi/4 (1e6 px)^2 / 0.82 x 20000² px: 3.83e20
}

TEST(SceneFile, RelativeImagePathsStartAtTheSceneFile) {
  std::string path = testing::TempDir() + "/rel_scene.json";
  std::ofstream(path) << R"({"init": {"method": "halftone", "image": "pic.png"}})";
  Scene s = load_scene(path);
  EXPECT_EQ(s.resolve(s.init.image), s.base_dir + "/pic.png");
  std::remove(path.c_str());
}

}  // namespace
}  // namespace sandpic

namespace sandpic {
namespace {

TEST(SceneFile, DigestNamesWhatTheModeReads) {
  Scene a;
  a.mode = Mode::Dem;
  Scene b = a;
  b.lattice.bulk = 1.2;  // the DEM does not read it
  b.description = "another text";
  EXPECT_EQ(scene_digest(a), scene_digest(b));
  b.dem.solver_iterations = 11;
  EXPECT_NE(scene_digest(a), scene_digest(b));
  Scene c = a;
  c.physics_seed = 2;
  EXPECT_NE(scene_digest(a), scene_digest(c));
  EXPECT_EQ(scene_digest(a).size(), 16u);
}

TEST(SceneFile, LatticeDigestReadsTheDevicesReleaseAndWaterOnly) {
  Scene a;  // lattice mode
  Scene b = a;
  b.dem.solver_iterations = 11;  // the DEM's own: not read
  b.dem.layers = Layers::Bcre;
  b.physics.restitution = 0.5;  // the lattice does not bounce
  EXPECT_EQ(scene_digest(a), scene_digest(b));
  for (auto change : std::vector<std::function<void(Scene&)>>{
           [](Scene& s) { s.dem.release_rate = 8000; }, [](Scene& s) { s.dem.water = false; },
           [](Scene& s) { s.dem.water_density_g_cm3 = 1.1; }, [](Scene& s) { s.dem.water_viscosity_pa_s = 2e-3; },
           [](Scene& s) { s.lattice.arrival = LatticeArrival::Release; }}) {
    Scene c = a;
    change(c);
    EXPECT_NE(scene_digest(a), scene_digest(c));
  }
}

TEST(SceneFile, ScaleKeepsTheRunOut) {
  Scene s;
  apply_scale(s, 0.5);
  EXPECT_EQ(s.lattice.runout_px, Scene{}.lattice.runout_px);
}

// validate's sweep comes from the registry: every point a key declares is a
// value the key accepts (numbers kept in range, integers whole), and a point
// that does not apply to a scene says so with null.
TEST(SceneFile, SweepPointsAreValuesTheKeyAccepts) {
  Scene s;
  int points = 0;
  for (const Field& f : scene_fields())
    for (const SweepPoint& p : f.sweep) {
      const ordered_json v = p.change(f, f.get(s), s);
      if (v.is_null()) continue;
      Scene t;
      EXPECT_NO_THROW(f.set(t, json::parse(v.dump()))) << f.path << " " << v.dump();
      ++points;
    }
  EXPECT_GE(points, 20);
  const Field& iterations = *find_field("dem.solver_iterations");
  s.dem.solver_iterations = 1;
  EXPECT_EQ(times(0.5).change(iterations, iterations.get(s), s), 1);  // within its range [1, 1000]
  s.dem.solver_iterations = 7;
  EXPECT_EQ(times(0.5).change(iterations, iterations.get(s), s), 3);
  const Field& arrival = *find_field("lattice.arrival");
  s.lattice.arrival = LatticeArrival::Release;  // landing order: no settling points
  for (const SweepPoint& p : arrival.sweep) EXPECT_TRUE(p.change(arrival, arrival.get(s), s).is_null());
}

TEST(SceneFile, CalibrationFileErrorsNameTheKeyOrFile) {
  const std::filesystem::path dir = test::fresh_folder();
  Scene s;
  s.lattice.calibration = (dir / "sandpic-no-such-calibration.json").string();
  try {
    with_calibration(s);
    FAIL() << "a missing calibration was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lattice.calibration"), std::string::npos) << e.what();
  }
  const auto bad = dir / "sandpic-bad-calibration.json";
  std::ofstream(bad) << R"({"lattice": {"repose_deg": [30, 30, 200, 30]}})";
  s.lattice.calibration = bad.string();
  try {
    with_calibration(s);
    FAIL() << "an angle of 200° was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lattice.repose_deg"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
  }
  std::ofstream(bad) << R"({"lattice": {"repose_deg": [40, 40, 35, 35], "bulk": 1.1}})";
  Scene good = with_calibration(s);
  EXPECT_DOUBLE_EQ((*good.lattice.repose_deg)[2], 35);
  EXPECT_DOUBLE_EQ(good.lattice.bulk, 1.1);
  std::filesystem::remove(bad);
}

// Keys a mode never reads: its own section's keys are read, the other's are
// not but for the device's release rate and water; a key given with --set is
// named even at its default, a scene's key only when it differs from it.
TEST(SceneFile, UnreadKeysAreTheOtherModesSection) {
  EXPECT_TRUE(read_in_mode("dem.cycle_steps", Mode::Dem));
  EXPECT_FALSE(read_in_mode("dem.cycle_steps", Mode::Lattice));
  EXPECT_TRUE(read_in_mode("dem.release_rate", Mode::Lattice));
  EXPECT_FALSE(read_in_mode("lattice.bulk", Mode::Dem));
  EXPECT_TRUE(read_in_mode("physics.friction", Mode::Dem));
  Scene s;
  EXPECT_TRUE(unread_keys(s, {}).empty());
  EXPECT_EQ(unread_keys(s, {"dem.cycle_steps", "physics.friction"}), std::vector<std::string>{"dem.cycle_steps"});
  apply_setting(s, "lattice.bulk=1.2");
  EXPECT_TRUE(unread_keys(s, {}).empty());
  apply_setting(s, "mode=\"dem\"");
  EXPECT_EQ(unread_keys(s, {}), std::vector<std::string>{"lattice.bulk"});
}

// The registry declares each key's kind, range, choices, readers and whether
// an area may set it; every default lies in its own range and choices.
TEST(SceneRegistry, EveryKeyDeclaresWhatItIsAndWhoReadsIt) {
  const Scene defaults;
  for (const Field& f : scene_fields()) {
    SCOPED_TRACE(f.path);
    EXPECT_FALSE(f.kind.empty());
    EXPECT_NE(f.readers, 0u);
    const ordered_json d = f.get(defaults);
    if (f.kind == "number" || f.kind == "integer") {
      ASSERT_LT(f.lo, f.hi);
      EXPECT_GE(d.get<double>(), f.lo);
      EXPECT_LE(d.get<double>(), f.hi);
    }
    if (f.kind == "choice") {
      EXPECT_NE(std::find(f.choices.begin(), f.choices.end(), d.get<std::string>()), f.choices.end());
    }
    Scene s;
    EXPECT_NO_THROW(f.set(s, d));  // a default is a value the key accepts
    const bool backend = f.path.starts_with("lattice.") || f.path.starts_with("dem.");
    if (!backend) {
      EXPECT_TRUE(read_in_mode(f, Mode::Lattice) || read_in_mode(f, Mode::Dem));
    }
  }
  // An area of the region makes its own initialization and segmentation
  // (paper §10, Fig. 17), nothing else.
  for (const Field& f : scene_fields())
    EXPECT_EQ(area_key(f.path),
              f.path.starts_with("init.") || f.path.starts_with("segment.") || f.path == "grains.proportions")
        << f.path;
  EXPECT_FALSE(read_in_mode("physics.restitution", Mode::Lattice));
  EXPECT_TRUE(read_in_mode("render.symmetric", Mode::Dem));
  EXPECT_FALSE(read_in_mode("no.such.key", Mode::Dem));
}

TEST(SceneRegistry, KeysAsJsonForTheStudio) {
  const ordered_json keys = keys_json();
  ASSERT_EQ(keys.size(), scene_fields().size());
  auto find = [&](const std::string& k) {
    for (const auto& e : keys)
      if (e["key"] == k) return e;
    return ordered_json();
  };
  const ordered_json friction = find("physics.friction");
  EXPECT_EQ(friction["kind"], "number");
  EXPECT_EQ(friction["min"], 0.0);
  EXPECT_EQ(friction["max"], 10.0);
  EXPECT_EQ(friction["default"], Scene{}.physics.friction);
  EXPECT_EQ(friction["read_by"], (ordered_json{"lattice", "dem", "lammps"}));
  // The LAMMPS mode reads the physics it maps (docs/lammps.md), not the
  // Bullet DEM's own keys (layers, step, stiffness).
  EXPECT_TRUE(read_in_mode("dem.rolling_resistance", Mode::Lammps));
  EXPECT_TRUE(read_in_mode("dem.water_viscosity_pa_s", Mode::Lammps));
  EXPECT_FALSE(read_in_mode("dem.layers", Mode::Lammps));
  EXPECT_FALSE(read_in_mode("dem.step_diameters", Mode::Lammps));
  EXPECT_FALSE(read_in_mode("lattice.resolution", Mode::Lammps));
  EXPECT_EQ(find("segment.method")["choices"],
            (ordered_json{"ellipses", "explicit", "cells", "sketch", "pattern"}));
  EXPECT_EQ(find("segment.method")["area"], true);
  EXPECT_EQ(find("preset")["choices"][0], "");
  EXPECT_EQ(find("window.width")["scaled"], true);
  EXPECT_FALSE(find("grains.colors").contains("min"));
}

}  // namespace
}  // namespace sandpic
