#include "src/plugin.h"

#include <dlfcn.h>

#include <filesystem>

#include "src/errors.h"

namespace sandpic {

std::vector<void*> load_plugin(const std::string& file, const std::string& built, const std::string& what,
                               std::initializer_list<const char*> symbols) {
  std::string tried, why;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string beside = ec ? std::string() : (exe.parent_path() / file).string();
  for (const std::string& path : {beside, built}) {
    if (path.empty() || tried.find(path) != std::string::npos) continue;
    if (void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
      std::vector<void*> found;
      for (const char* name : symbols)
        if (void* f = dlsym(h, name)) found.push_back(f);
      if (found.size() == symbols.size()) return found;
      why = path + " lacks " + std::to_string(symbols.size() - found.size()) + " of its functions";
    } else {
      why = dlerror();
    }
    tried += (tried.empty() ? "" : ", ") + path;
  }
  throw InputError("cannot load " + what + " " + file + " (tried " + tried + "): " + why);
}

}  // namespace sandpic
