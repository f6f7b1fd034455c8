#pragma once
// A catalogue of stiff and extreme scenes, each run through the CLI
// as a user runs it (a child process: a crash or a hang is a finding, not the
// end of the catalogue), and what became of it: a picture with every grain
// accounted for, a one-line error (exit 2), a divergence report (exit 3), or
// a failure of sandpic's promises.
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sandpic {

enum class Outcome { Picture, Error, Divergence, Fail };
std::string outcome_name(Outcome o);

struct StressCase {
  std::string name;   // "friction-0"
  std::string about;  // what it sets, for the table
  // The scene file's text; may write the files it names into `dir`.
  std::function<std::string(const std::string& dir)> scene;
  std::vector<std::string> args;   // more render options
  std::vector<std::string> modes;  // "lattice", "dem"
  std::set<Outcome> expect;        // anything else is a failure
  std::string mention;             // an error must name this (a key, a file, "line")
};

// The catalogue; `quick` sizes the scenes for CI (about 2,000 grains).
std::vector<StressCase> stress_cases(bool quick);

// What a child process did.
struct ChildRun {
  int exit_code = -1;  // -1: killed by a signal or the timeout
  int signal = 0;
  bool timed_out = false;
  double seconds = 0;
};
ChildRun run_child(const std::vector<std::string>& argv, const std::string& out_file, const std::string& err_file,
                   double timeout_s);

// One case in one mode, judged from the files it left.
struct StressRow {
  std::string name, about, mode;
  Outcome outcome = Outcome::Fail;
  int exit_code = -1;
  double seconds = 0;
  int64_t released = -1, in_picture = -1;  // -1: no picture
  double overlap_px = -1, overlap_diameters = -1, kinetic_energy_j = -1;  // -1: not reported (lattice, errors)
  int substeps = 0;
  std::string message;  // the error line, or why it failed
};

struct StressFiles {
  std::string picture, stats, err;  // the render's -o, --stats, and its stderr
  std::string sentinel;             // bytes the picture held before the run
};
// Outcome of one run: exit 0 must leave a decodable picture of the window's
// size (as the stats give it) and stats with every grain in the picture and no NaN; exit 2 or 3
// one line on stderr naming `mention`, the old picture untouched and no
// stats; anything else, or an outcome outside `expect`, is Fail.
StressRow judge(const StressCase& c, const std::string& mode, const ChildRun& run, const StressFiles& f);

struct StressOptions {
  std::string exe;  // the sandpic binary to run
  std::string out = "stress";  // folder: stress.md, stress.json, cases/
  bool quick = false;
  bool with_dem = true;
  std::vector<std::string> only;  // case names; empty: all
  double timeout_s = 0;           // per run; 0: 1800 s
  int threads = 0;                // runs at once; 0: one per core
};
std::vector<StressRow> run_stress(const StressOptions& opt, const std::function<void(const StressRow&)>& done);

std::string stress_markdown(const std::vector<StressRow>& rows, const StressOptions& opt);
nlohmann::ordered_json stress_json(const std::vector<StressRow>& rows, const StressOptions& opt);

}  // namespace sandpic
