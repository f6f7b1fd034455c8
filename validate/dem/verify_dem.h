#pragma once
// sandpic verify-dem: the DEM checked against answers it does not compute
// itself. Single grains against closed forms (settling in the water,
// restitution, an incline, rolling resistance, a grain in a notch), piles
// against each other (the heap angle against friction and rolling
// resistance, creep, three-layer against all-dynamic, half the time step).
// Each case says what it measured, what was expected, within what, and
// whether that holds; --quick runs the piles at a few hundred grains with
// the looser tolerances it states.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "src/scene_file.h"

namespace sandpic {

struct VerifyOptions {
  bool quick = false;
  int threads = 0;                 // 0: every core (TBB's default)
  std::vector<std::string> only;   // case ids; empty: all
  // "key=value" set on every pile case's scene (heap, creep, layers, step),
  // after the keys the cases vary (run_verify_dem refuses those).
  std::vector<std::string> sets;
  // The layer models held against all-dynamic: the layers case takes each
  // of them, heap, step and engine-piles three-layer if listed. Only
  // all-dynamic: those run all-dynamic alone and the layers case not at all.
  std::vector<Layers> layer_models = {Layers::Three, Layers::Bcre};
  std::function<void(const std::string&)> log = [](const std::string&) {};
};

// One measured figure against its expectation: |measured − expected| ≤
// tolerance (Within), measured ≤ expected (AtMost) or ≥ (AtLeast).
struct VerifyCheck {
  enum class Kind { Within, AtMost, AtLeast };
  std::string name, unit;
  double measured = 0, expected = 0, tolerance = 0;
  Kind kind = Kind::Within;
  bool pass() const;
  std::string rule() const;  // "within ±0.5 of 12.3", "at most 0.1", ...
};

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  bool points = false;  // markers only, else a line
};
struct VerifyPlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
};

struct VerifyCase {
  VerifyCase() = default;
  VerifyCase(std::string i, std::string t, std::string ref) : id(std::move(i)), title(std::move(t)), reference(std::move(ref)) {}
  std::string id, title, reference;  // reference: what the expectation comes from
  std::vector<VerifyCheck> checks;
  std::vector<VerifyPlot> plots;
  std::vector<std::pair<std::string, cv::Mat>> pictures;  // caption, 8-bit BGR
  std::vector<std::string> notes;
  double seconds = 0;
  bool pass() const;
};

struct VerifyReport {
  bool quick = false;
  std::vector<std::string> sets;  // VerifyOptions::sets
  std::vector<VerifyCase> cases;
  std::vector<std::pair<std::string, std::string>> not_run;  // cases these options leave out: id, why
  double seconds = 0;
  bool pass() const;
};

// The case ids, in the order they run: settling, restitution, incline,
// rolling, notch, heap, creep, layers, step, engines, engine-piles (the
// full run only).
const std::vector<std::string>& verify_case_ids();

// Throws InputError (exit 2) for an id of opt.only that is not a case and
// for a setting of opt.sets that is not a scene key's or is one the pile
// cases vary themselves (dem.layers, physics.friction, dem.rolling_resistance,
// the seeds, the mode). run_verify_dem checks first; the CLI too, before it
// makes the report's folder.
void check_verify_options(const VerifyOptions& opt);
VerifyReport run_verify_dem(const VerifyOptions& opt);

ordered_json verify_json(const VerifyReport& r);
std::string verify_html(const VerifyReport& r);

}  // namespace sandpic
