// sandpic export-lammps: a scene's LAMMPS deck without running it, for a
// machine or cluster with more cores (physics/lammps_simulator.h); render
// --mode lammps --from-dump draws what it wrote.
#include <cstdio>

#include "src/cli/cli_common.h"
#include "src/output.h"
#include "src/pipeline.h"
#include "physics/lammps_simulator.h"

namespace sandpic {
namespace {

struct ExportLammpsCommand {
  SceneOptions scene;
  std::string out;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "export-lammps", "write a scene's LAMMPS deck (in.sandpic, atoms.txt, run.sh, deck.json, scene.json) without running it");
    scene.add_to(cmd);
    cmd->add_option("-o,--out", out, "folder for the deck")->required();
    cmd->callback([this] { run(); });
  }

  void run() {
    Scene s = scene.build();
    s.mode = Mode::Lammps;
    while (out.size() > 1 && out.back() == '/') out.pop_back();
    check_folder(out);
    const Prepared p = prepare(s);
    const ordered_json deck = export_lammps(p.input(s), out);
    // The scene as run, seeds and scale included: render draws the dump with it.
    write_atomic(out + "/scene.json", to_json(s).dump(2) + "\n");
    std::printf("sandpic export-lammps: %lld grains, %lld steps at most (time step %.3g s) in %s\n"
                "  run:  sh %s/run.sh   (RANKS=N for mpirun -np N, LAUNCHER='srun -n N' on a cluster)\n"
                "  draw: sandpic render %s/scene.json --from-dump %s/final.dump -o picture.png\n",
                (long long)p.init.grains.size(), (long long)deck["max_steps"].get<int64_t>(),
                deck["time_step_s"].get<double>(), out.c_str(), out.c_str(), out.c_str(), out.c_str());
  }
};

}  // namespace

std::shared_ptr<void> add_lammps_command(CLI::App& app) {
  auto c = std::make_shared<ExportLammpsCommand>();
  c->add_to(app);
  return c;
}

}  // namespace sandpic
