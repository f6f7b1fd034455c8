#pragma once
// paper §9's heuristic rules as named bases a scene file starts from
// ("preset": "desert"), its own keys read over them.
#include <string>
#include <vector>

namespace sandpic {

struct Preset {
  std::string name;
  std::string about;  // the rule of §9 it follows, for `sandpic scene --presets`
  std::string json;   // scene keys
};

const std::vector<Preset>& presets();
const Preset* find_preset(const std::string& name);  // nullptr if unknown

}  // namespace sandpic
