// sandpic stress, the catalogue of stiff and extreme scenes run in
// both modes, as a table in Markdown and JSON.
#include <cstdio>
#include <filesystem>

#include "src/cli/cli_common.h"
#include "src/errors.h"
#include "src/output.h"
#include "src/progress.h"
#include "src/simulator.h"
#include "validate/stress/stress.h"

namespace sandpic {
namespace {

struct StressCommand {
  StressOptions opt;
  std::string only;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "stress", "run the catalogue of stiff and extreme scenes in both modes; writes stress.md and stress.json");
    cmd->add_flag("--quick", opt.quick, "small scenes (about 2,000 grains), as CI runs them");
    cmd->add_option("--out", opt.out, "folder for stress.md, stress.json and each run's files in cases/")
        ->capture_default_str();
    cmd->add_option("--only", only, "case names, comma-separated (see stress.md for the list)");
    cmd->add_option("--timeout", opt.timeout_s, "seconds a run may take before it counts as a hang "
                                                "(0: 1800)")
        ->check(CLI::Range(0.0, 1e6));
    cmd->add_option("--threads", opt.threads, "runs at once, each a child process (0: one per core); a run's time "
                                              "grows with what runs beside it")
        ->check(CLI::Range(0, 1024));
    cmd->callback([this] { run(); });
  }

  void run() {
    if (!only.empty()) {
      opt.only = list_option<std::string>("--only", only, [](const std::string& i) {
        for (const StressCase& c : stress_cases(true))
          if (c.name == i) return i;
        throw InputError("--only: no case '" + i + "'");
      });
    }
    check_folder(opt.out);
    opt.exe = std::filesystem::read_symlink("/proc/self/exe").string();
    Scene dem;
    dem.mode = Mode::Dem;
    try {
      make_simulator(dem);
    } catch (const InputError&) {
      opt.with_dem = false;  // a build without Bullet: the lattice alone
    }
    const bool tty = Progress::stderr_is_terminal();
    int index = 0;
    auto rows = run_stress(opt, [&](const StressRow& r) {
      ++index;
      if (tty)
        std::fprintf(stderr, "stress: %3d  %-22s %-8s %-20s %7.2f s  %s\n", index, r.name.c_str(), r.mode.c_str(),
                     outcome_name(r.outcome).c_str(), r.seconds, r.message.substr(0, 80).c_str());
    });
    write_atomic(opt.out + "/stress.md", stress_markdown(rows, opt));
    write_atomic(opt.out + "/stress.json", stress_json(rows, opt).dump(2) + "\n");
    int fails = 0, pictures = 0, errors = 0, divergences = 0;
    for (const StressRow& r : rows) {
      fails += r.outcome == Outcome::Fail;
      pictures += r.outcome == Outcome::Picture;
      errors += r.outcome == Outcome::Error;
      divergences += r.outcome == Outcome::Divergence;
    }
    std::printf("sandpic stress: %zu runs: %d pictures, %d errors (exit 2), %d divergence reports (exit 3), %d failed%s; "
                "%s/stress.md\n",
                rows.size(), pictures, errors, divergences, fails, opt.with_dem ? "" : " (no DEM: built without Bullet)",
                opt.out.c_str());
    if (fails) throw CheckFailed(std::to_string(fails) + " of " + std::to_string(rows.size()) +
                                  " stress runs broke a promise; see " + opt.out + "/stress.md");
  }
};

}  // namespace

std::shared_ptr<void> add_stress_command(CLI::App& app) {
  auto cmd = std::make_shared<StressCommand>();
  cmd->add_to(app);
  return cmd;
}

}  // namespace sandpic
