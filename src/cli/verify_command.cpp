// sandpic verify-dem: the DEM checked against closed forms and against
// itself (validate/dem/verify_dem.h); report.json and report.html.
#include <cstdio>
#include <filesystem>

#include "src/cli/cli_common.h"
#include "src/errors.h"
#include "src/output.h"
#include "src/progress.h"
#if SANDPIC_WITH_BULLET
#include "validate/dem/verify_dem.h"
#endif

namespace sandpic {
namespace {

struct VerifyCommand {
  bool quick = false;
  std::string out, only, layers = "three,bcre";
  std::vector<std::string> sets;
  int threads = 0;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "verify-dem", "check the DEM against closed-form answers and itself; writes report.json and report.html");
    cmd->add_flag("--quick", quick, "piles of a few hundred grains, looser tolerances (2-4 minutes on 2 cores; ctest runs it)");
    cmd->add_option("--out", out, "folder for report.json and report.html")->required();
    cmd->add_option("--only", only, "case ids, comma-separated (settling, restitution, incline, rolling, notch, heap, "
                                    "creep, layers, step, engines, engine-piles: the full run only)");
    cmd->add_option("--set", sets, "KEY=VALUE on every pile case's scene (heap, creep, layers, step, engine-piles), as render's "
                                   "--set; repeatable; not the keys the cases vary (layers, friction, rolling "
                                   "resistance, seeds)");
    cmd->add_option("--layers", layers, "the layer models held against all-dynamic, comma-separated: the layers case "
                                        "takes each, heap, step and engine-piles three if listed; 'all-dynamic' alone: "
                                        "no comparison, the layers case not run")
        ->capture_default_str();
    cmd->add_option("--threads", threads, "worker threads (0: all cores); the results do not depend on it")
        ->check(CLI::Range(0, 1024));
    cmd->callback([this] { run(); });
  }

  void run() {
#if SANDPIC_WITH_BULLET
    VerifyOptions opt;
    opt.quick = quick;
    opt.threads = threads;
    if (!only.empty()) opt.only = list_option<std::string>("--only", only, [](const std::string& i) { return i; });
    opt.sets = sets;
    opt.layer_models = layers_list(layers);
    check_verify_options(opt);  // before the folder is made
    check_folder(out);
    const bool tty = Progress::stderr_is_terminal();
    opt.log = [tty](const std::string& line) {
      if (tty) std::fprintf(stderr, "verify-dem: %s\n", line.c_str());
    };
    const VerifyReport report = run_verify_dem(opt);
    std::filesystem::create_directories(out);
    write_atomic(out + "/report.json", verify_json(report).dump(2) + "\n");
    write_atomic(out + "/report.html", verify_html(report));
    int failed = 0;
    for (const VerifyCase& c : report.cases) {
      int bad = 0;
      for (const VerifyCheck& k : c.checks) bad += !k.pass();
      failed += bad > 0;
      std::printf("%-12s %-46s %s (%.0f s)\n", c.id.c_str(), c.title.c_str(),
                  bad ? (std::to_string(bad) + " of " + std::to_string(c.checks.size()) + " checks fail").c_str() : "pass",
                  c.seconds);
    }
    for (const auto& [id, why] : report.not_run) std::printf("%-12s %s\n", id.c_str(), why.c_str());
    std::printf("sandpic verify-dem%s: %zu cases, %d failed, %.0f s; %s/report.html\n", quick ? " --quick" : "",
                report.cases.size(), failed, report.seconds, out.c_str());
    if (failed) throw CheckFailed(std::to_string(failed) + " of " + std::to_string(report.cases.size()) +
                                  " verify-dem cases failed; see " + out + "/report.html");
#else
    throw InputError("verify-dem needs the DEM mode, and this sandpic was built without Bullet "
                     "(cmake -DSANDPIC_WITH_BULLET=ON)");
#endif
  }
};

}  // namespace

std::shared_ptr<void> add_verify_command(CLI::App& app) {
  auto cmd = std::make_shared<VerifyCommand>();
  cmd->add_to(app);
  return cmd;
}

}  // namespace sandpic
