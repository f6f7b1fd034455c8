// Where a simulation's time goes: a step is a short fixed list of named
// stages (as Box2D's b2Profile), and each stage's wall time is summed over
// the run and reported in the stats. Timing never feeds back into the run:
// the picture does not depend on it.
#pragma once

#include <array>
#include <chrono>
#include <string_view>

#include "src/scene_file.h"  // ordered_json

namespace sandpic {

template <size_t N>
class StageTimes {
 public:
  explicit constexpr StageTimes(std::array<std::string_view, N> names) : names_(names) {}

  // Runs f() and adds its wall time to stage i.
  template <class F>
  void time(size_t i, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    seconds_[i] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // Runs f() and adds its wall time to stage i, less what stage `inner`
  // gained meanwhile (a stage that runs within f, reported on its own).
  template <class F>
  void time_without(size_t i, size_t inner, F&& f) {
    const double before = seconds_[inner];
    time(i, f);
    seconds_[i] -= seconds_[inner] - before;
  }

  // {"name": seconds, ...} in the stages' order.
  ordered_json json() const {
    ordered_json out = ordered_json::object();
    for (size_t i = 0; i < N; ++i) out[std::string(names_[i])] = seconds_[i];
    return out;
  }

 private:
  std::array<std::string_view, N> names_;
  std::array<double, N> seconds_{};
};

}  // namespace sandpic
