// libFuzzer target for the scene parser: the input's bytes are a
// scene file's text, taken through what `sandpic render SCENE.json` does with
// it before any image is read: parse and apply (load_scene without the file),
// validate, every area's scene, then --scale 0.5. Refusals a user sees as
// "sandpic: error: ..." (exit 2) are expected; anything else aborts, so
// libFuzzer keeps the input as a crash. Built by SANDPIC_FUZZ, run by .ci/fuzz.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "src/errors.h"
#include "src/scene_file.h"

namespace {

using namespace sandpic;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_scene: %s\n", what.c_str());
  std::abort();
}

// Runs `step`; true when it refused the scene the way the CLI reports a bad
// input (cli_main: InputError, and nlohmann::json::exception as "bad value").
template <class F>
bool refused(F step) {
  try {
    step();
    return false;
  } catch (const InputError&) {
    return true;
  } catch (const nlohmann::json::exception&) {
    return true;
  }
}

// A scene that loaded and validated must write itself out (sandpic scene,
// the stats) and read back to a valid scene with the same digest: that is what
// lets a run be reproduced from its scene dump. Nothing may throw here.
void check_round_trip(const Scene& s) {
  const std::string digest = scene_digest(s);
  std::string text;
  Scene back;
  try {
    text = to_json(s).dump(2);
    back = scene_from_text(text, "round trip", s.base_dir);
    validate(back);
  } catch (const std::exception& e) {
    finding(std::string("a valid scene does not read back: ") + e.what() + "\n" + text);
  }
  if (scene_digest(back) != digest) finding("the scene read back has another digest:\n" + text);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Scene s;
  if (refused([&] { s = scene_from_text(text, "fuzz.json", "."); })) return 0;
  if (refused([&] { validate(s); })) return 0;
  for (size_t i = 0; i < s.regions.size(); ++i)
    if (refused([&] { area_scene(s, i); })) finding("validate passed but area " + std::to_string(i) + " is refused");
  check_round_trip(s);
  // --scale 0.5 may refuse (a length under its key's minimum once halved),
  // and so may validate afterwards; neither may do anything else.
  if (refused([&] { apply_scale(s, 0.5); })) return 0;
  refused([&] { validate(s); });
  return 0;
}
