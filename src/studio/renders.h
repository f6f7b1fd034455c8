#pragma once
// The studio's final renders: the DEM in the background, one at a
// time, on one thread, so the live preview keeps the other core. A finished
// render is never lost: its picture, scene and stats go to `dir` (written
// atomically) before it is reported done.
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "src/scene_file.h"

namespace sandpic::studio {

// A final render asked for while one runs: the server answers 409.
struct Busy : InputError {
  using InputError::InputError;
};

struct RenderJob {
  int id = 0;
  std::string stem;  // file names in the renders' folder: stem.png, .json, .stats.json
  std::atomic<double> fraction{0};
  std::atomic<bool> done{false};
  std::atomic<bool> cancel{false};  // asked to stop: the run stops at its next progress update
  bool cancelled = false;           // set before done, when it stopped on request (nothing written)
  std::string error;    // set before done, when it failed
  std::string picture;  // path of the PNG, set before done, when it succeeded
};

class Renders {
 public:
  explicit Renders(std::string dir) : dir_(std::move(dir)) {}
  ~Renders();  // waits for a running render: its picture is still written

  // Starts rendering `s` in s.mode; throws Busy if one is running, InputError
  // if the mode cannot run in this build (no Bullet: names the key 'mode').
  int start(const Scene& s);
  // nullptr for an unknown id.
  std::shared_ptr<const RenderJob> job(int id) const;
  // Asks render `id` to stop; false if there is no such render or it is
  // done already. The worker is free for the next render once the job says
  // done (within one progress update: a DEM step cycle).
  bool cancel(int id);
  const std::string& dir() const { return dir_; }

 private:
  void run(const Scene& s, std::shared_ptr<RenderJob> job);
  std::string dir_;
  mutable std::mutex mutex_;
  std::map<int, std::shared_ptr<RenderJob>> jobs_;
  std::thread worker_;
  int next_id_ = 1;
};

// {"id", "done", "cancelled", "fraction", "error", "picture"} for GET /api/render/<id>.
ordered_json status_json(const RenderJob& job);

}  // namespace sandpic::studio
