#pragma once
// verify-dem's cases (validate/dem/verify_dem.h), one function each.
#include "validate/dem/verify_dem.h"

namespace sandpic::verify {

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

}  // namespace sandpic::verify
