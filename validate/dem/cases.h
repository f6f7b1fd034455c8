#pragma once
// verify-dem's cases (validate/dem/verify_dem.h), one function each.
#include <cstdio>
#include <string>

#include "validate/dem/verify_dem.h"

namespace sandpic::verify {

// A number in a check's name or a note, printf-style ("%.1f").
inline std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// A check that |measured − expected| ≤ tolerance, or measured ≤ bound.
inline VerifyCheck within(std::string name, double measured, double expected, double tolerance, std::string unit) {
  return {std::move(name), std::move(unit), measured, expected, tolerance, VerifyCheck::Kind::Within};
}
inline VerifyCheck at_most(std::string name, double measured, double bound, std::string unit) {
  return {std::move(name), std::move(unit), measured, bound, 0, VerifyCheck::Kind::AtMost};
}

// Single grains in the DEM's own world (physics/probe.h), against closed forms.
VerifyCase settling(const VerifyOptions& opt);
VerifyCase restitution(const VerifyOptions& opt);
VerifyCase incline(const VerifyOptions& opt);
VerifyCase rolling(const VerifyOptions& opt);
VerifyCase notch(const VerifyOptions& opt);

// Piles, through the pipeline.
VerifyCase heap(const VerifyOptions& opt);
VerifyCase creep(const VerifyOptions& opt);
VerifyCase layers(const VerifyOptions& opt);
VerifyCase step(const VerifyOptions& opt);

// The Bullet DEM against LAMMPS (physics/lammps_deck.h) from one placed
// configuration: a column of grains collapsing in the water.
VerifyCase engines(const VerifyOptions& opt);
// And on whole piles, each engine pouring its own (full run only).
VerifyCase engine_piles(const VerifyOptions& opt);
// Where LAMMPS's lmp is not installed: a failing check in c saying so, and true.
bool lammps_missing(VerifyCase& c);

}  // namespace sandpic::verify
