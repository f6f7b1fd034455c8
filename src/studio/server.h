#pragma once
// sandpic studio: a local web page to design a scene, with a live
// lattice preview and final DEM renders in the background. The page ships
// inside the binary (page/, embedded by CMake); nothing is fetched.
#include <memory>
#include <string>

namespace sandpic::studio {

struct ServerOptions {
  std::string host = "127.0.0.1";  // loopback unless told otherwise
  int port = 8080;                 // 0: any free port
  std::string root = ".";          // working folder: scene files' paths must stay inside it
  std::string renders = "studio-renders";  // finished final renders, under root unless absolute
  std::string scene_path;          // the starting scene; empty: the default scene
};

class Server {
 public:
  // Reads the starting scene: throws InputError if it is bad.
  explicit Server(const ServerOptions& opt);
  ~Server();  // waits for a running final render (its picture is kept)
  // Binds host:port; returns the port (the one chosen when port was 0).
  // Throws InputError if the address cannot be bound.
  int bind();
  void run();   // serves until stop()
  void stop();  // from another thread

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sandpic::studio
