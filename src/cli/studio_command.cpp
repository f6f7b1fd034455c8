// sandpic studio, the scene designer's local web page.
#include <cstdio>

#include "src/cli/cli_common.h"
#include "src/studio/api.h"
#include "src/studio/server.h"

namespace sandpic {
namespace {

struct StudioCommand {
  studio::ServerOptions opt;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("studio", "serve a local web page to design a scene, with a live preview");
    cmd->add_option("scene", opt.scene_path, "the scene to start from (JSON); none: the built-in default scene");
    cmd->add_option("--port", opt.port, "port (0: any free one)")->capture_default_str()->check(CLI::Range(0, 65535));
    cmd->add_option("--host", opt.host, "address to listen on; anything but loopback lets other machines in")
        ->capture_default_str();
    cmd->add_option("--renders", opt.renders, "folder for finished final renders (kept)")->capture_default_str();
    cmd->callback([this] { run(); });
  }

  void run() {
    // The page runs renders and reads files under the working folder: open
    // to anyone who can reach the address.
    if (!studio::is_loopback(opt.host))
      std::fprintf(stderr, "sandpic: note: --host %s: the studio is reachable from other machines\n", opt.host.c_str());
    studio::Server server(opt);
    const int port = server.bind();
    std::printf("sandpic studio: http://%s:%d/  (Ctrl-C to stop; final renders go to %s/)\n", opt.host.c_str(), port,
                opt.renders.c_str());
    std::fflush(stdout);
    server.run();
  }
};

}  // namespace

std::shared_ptr<void> add_studio_command(CLI::App& app) {
  auto cmd = std::make_shared<StudioCommand>();
  cmd->add_to(app);
  return cmd;
}

}  // namespace sandpic
