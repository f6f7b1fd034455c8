#include "src/errors.h"

namespace sandpic {

InputError key_error(const std::string& path, const std::string& what) {
  return InputError("scene key '" + path + "': " + what);
}

}  // namespace sandpic
