#pragma once
// User-fixable problems are values with a message, reported once at the CLI
// edge with the right exit code (DEVELOPERS.md, Standards).
#include <stdexcept>
#include <string>

namespace sandpic {

// Bad scene, bad key, missing or corrupt file: exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A scene key with a bad value; the message names the key path.
InputError key_error(const std::string& path, const std::string& what);

// A simulation that failed or diverged: exit code 3.
struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A run stopped on request (the studio's cancel button): nothing is written.
struct Cancelled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A check that caught sandpic breaking one of its own promises (sandpic
// stress): exit code 1.
struct CheckFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace sandpic
