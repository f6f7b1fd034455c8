#include "src/studio/renders.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <ctime>

#include <tbb/task_arena.h>

#include "src/errors.h"
#include "src/output.h"
#include "src/pipeline.h"

namespace sandpic::studio {

Renders::~Renders() {
  if (worker_.joinable()) worker_.join();
}

int Renders::start(const Scene& s) {
  // The studio runs no other program: LAMMPS is the command line's alone.
  if (s.mode == Mode::Lammps) throw key_error("mode", "the studio does not run LAMMPS; use sandpic render --mode lammps");
  // Fails now, not in the background, when this build has no such backend.
  auto probe = make_simulator(s);
  std::lock_guard lock(mutex_);
  if (worker_.joinable()) {
    if (!jobs_.rbegin()->second->done) throw Busy("a final render is already running (one at a time)");
    worker_.join();
  }
  check_folder(dir_);
  auto job = std::make_shared<RenderJob>();
  job->id = next_id_++;
  // The start time in the name: a studio started again later numbers from 1
  // again and must not write over an earlier session's renders.
  char when[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y%m%d-%H%M%S", std::gmtime(&now));
  job->stem = "render-" + std::string(when) + "-" + std::to_string(job->id) + "-seed-" + std::to_string(s.seed);
  jobs_[job->id] = job;
  worker_ = std::thread([this, s, job] { run(s, job); });
  return job->id;
}

std::shared_ptr<const RenderJob> Renders::job(int id) const {
  std::lock_guard lock(mutex_);
  auto it = jobs_.find(id);
  return it == jobs_.end() ? nullptr : it->second;
}

bool Renders::cancel(int id) {
  std::lock_guard lock(mutex_);
  auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second->done) return false;
  it->second->cancel = true;
  return true;
}

void Renders::run(const Scene& s, std::shared_ptr<RenderJob> job) {
  // Two cores: the DEM gets one thread at a lower priority, so the live
  // preview (the other core, TBB's default arena) stays within its few
  // hundred milliseconds.
  setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), 10);
  tbb::task_arena one(1);
  try {
    one.execute([&] {
      auto sim = make_simulator(s);
      RunOptions opt;
      opt.fraction = &job->fraction;
      opt.cancel = &job->cancel;
      RunResult run = run_pipeline(s, *sim, opt);
      const std::string base = dir_ + "/" + job->stem;
      write_atomic(base + ".json", to_json(s).dump(2));
      write_atomic(base + ".stats.json", run.stats.dump(2));
      write_atomic(base + ".png", std::string_view(reinterpret_cast<const char*>(run.png.data()), run.png.size()));
      job->picture = base + ".png";
    });
  } catch (const Cancelled&) {
    job->cancelled = true;
    job->error = "cancelled";
  } catch (const std::exception& e) {
    job->error = e.what();
  }
  job->done = true;
}

ordered_json status_json(const RenderJob& job) {
  const bool done = job.done;  // read first: error and picture are set before it
  return {{"id", job.id},
          {"done", done},
          {"cancelled", done && job.cancelled},
          {"fraction", done && job.error.empty() ? 1.0 : job.fraction.load()},
          {"error", done ? job.error : ""},
          {"picture", done ? job.picture : ""}};
}

}  // namespace sandpic::studio
