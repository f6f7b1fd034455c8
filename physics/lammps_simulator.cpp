// The LAMMPS backend: write the deck, run `lmp` (a progress bar from its
// thermo lines), read the final positions back, check them, draw them.
#include "physics/lammps_simulator.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "physics/dem_params.h"
#include "physics/lammps_deck.h"
#include "physics/raster.h"
#include "src/errors.h"
#include "src/output.h"
#include "src/scene_file.h"

namespace sandpic {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string t; in >> t;) w.push_back(t);
  return w;
}

std::string run_script(const LammpsDeck& d) {
  return "#!/bin/sh\n"
         "# sandpic's LAMMPS deck (" + std::to_string(d.grain_of_atom.size()) +
         " grains). Run it here, on one machine or under a cluster's scheduler:\n"
         "#   sh run.sh                      one rank\n"
         "#   RANKS=8 sh run.sh              mpirun -np 8\n"
         "#   LAUNCHER='srun -n 256' sh run.sh\n"
         "# then draw the picture: sandpic render scene.json --from-dump final.dump -o picture.png\n"
         "cd \"$(dirname \"$0\")\" || exit 2\n"
         "export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1\n"
         "exec ${LAUNCHER:-mpirun -np ${RANKS:-1}} lmp -in in.sandpic -log log.lammps -nocite\n";
}

std::string atoms_text(const LammpsDeck& d) {
  std::string t = "# LAMMPS atom id -> sandpic grain id\n";
  for (size_t i = 0; i < d.grain_of_atom.size(); ++i) t += std::to_string(i + 1) + " " + std::to_string(d.grain_of_atom[i]) + "\n";
  return t;
}

ordered_json deck_json(const LammpsDeck& d) {
  const LammpsContact& c = d.contact;
  return ordered_json{{"time_step_s", c.dt},
                      {"contact",
                       {{"model", "hertz, tsuji damping, mindlin tangential, sds rolling"},
                        {"kn", c.kn},
                        {"kt", c.kt},
                        {"rolling_kr", c.kr},
                        {"rolling_gamma", c.gamma_r},
                        {"design_load", c.load},
                        {"design_overlap_px", c.target_overlap_px},
                        {"landing_overlap_px", c.landing_overlap_px}}},
                      {"release_end_s", d.release_end_s},
                      {"settle_limit_s", d.settle_limit_s},
                      {"settle_speed_px_s", d.settle_speed_px_s},
                      {"creations_delayed", d.delayed},
                      {"creations_late_mean_s", d.late_mean_s},
                      {"creations_late_max_s", d.late_max_s},
                      {"release_steps", d.release_steps},
                      {"max_steps", d.max_steps}};
}

std::string on_path(const std::string& name);

// A child process whose output we read; killed if we leave early. All it
// needs is made before fork(): in the child of a threaded process only
// async-signal-safe calls are allowed (another thread may hold malloc's lock).
class Child {
 public:
  Child(const std::vector<std::string>& argv, const std::string& dir) {
    std::string exe = argv.front().find('/') == std::string::npos ? on_path(argv.front()) : argv.front();
    if (exe.empty()) exe = argv.front();
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    // OpenMPI refuses root without these; one OpenMP thread per rank.
    std::vector<std::string> env_text = {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1", "OMP_NUM_THREADS=1"};
    for (char** e = environ; *e; ++e) {
      const std::string v = *e;
      if (v.rfind("OMPI_ALLOW_RUN_AS_ROOT", 0) != 0 && v.rfind("OMP_NUM_THREADS=", 0) != 0) env_text.push_back(v);
    }
    std::vector<char*> env;
    for (std::string& v : env_text) env.push_back(v.data());
    env.push_back(nullptr);
    int fds[2];
    if (pipe(fds) != 0) throw SimulationError("lammps: cannot make a pipe");
    const pid_t parent = getpid();
    pid_ = fork();
    if (pid_ < 0) throw SimulationError("lammps: cannot start a process");
    if (pid_ == 0) {
      // Dies with sandpic (Ctrl-C reaches both: same process group).
      prctl(PR_SET_PDEATHSIG, SIGTERM);
      if (getppid() != parent) _exit(127);
      dup2(fds[1], 1), dup2(fds[1], 2);
      close(fds[0]), close(fds[1]);
      if (chdir(dir.c_str()) != 0) _exit(127);
      execve(exe.c_str(), args.data(), env.data());
      _exit(127);
    }
    close(fds[1]);
    out_ = fdopen(fds[0], "r");
  }
  ~Child() {
    if (out_) fclose(out_);
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool line(std::string& l) {
    l.clear();
    for (int c; (c = fgetc(out_)) != EOF;) {
      if (c == '\n') return true;
      l += char(c);
    }
    return !l.empty();
  }
  int wait() {
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

 private:
  pid_t pid_ = -1;
  FILE* out_ = nullptr;
};

// A temporary folder, removed unless kept.
struct Folder {
  std::string path;
  bool temporary = false;
  ~Folder() {
    if (temporary && !path.empty()) {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  }
};

}  // namespace

std::vector<DumpAtom> read_lammps_dump(const std::string& path, size_t atoms) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the LAMMPS dump");
  std::string l;
  int64_t n = -1;
  std::vector<std::string> cols;
  while (std::getline(in, l)) {
    if (l.rfind("ITEM: NUMBER OF ATOMS", 0) == 0 && std::getline(in, l)) n = std::atoll(l.c_str());
    if (l.rfind("ITEM: ATOMS", 0) == 0) {
      cols = words(l.substr(11));
      break;
    }
  }
  auto col = [&](const char* name) {
    auto it = std::find(cols.begin(), cols.end(), name);
    if (it == cols.end()) throw InputError(path + ": not a dump of sandpic's deck (no column '" + name + "')");
    return size_t(it - cols.begin());
  };
  const size_t ci = col("id"), cx = col("x"), cy = col("y"), cvx = col("vx"), cvy = col("vy");
  if (n != int64_t(atoms))
    throw InputError(path + ": " + std::to_string(n) + " atoms where the scene's deck has " + std::to_string(atoms) +
                     " (a dump of another scene, or of a run that did not finish?)");
  std::vector<DumpAtom> a(atoms);
  std::vector<bool> seen(atoms, false);
  for (int64_t i = 0; i < n; ++i) {
    if (!std::getline(in, l)) throw InputError(path + ": ends after " + std::to_string(i) + " of its atoms");
    const auto w = words(l);
    if (w.size() < cols.size()) throw InputError(path + ": a short line: " + l);
    const int64_t id = std::atoll(w[ci].c_str());
    if (id < 1 || id > int64_t(atoms) || seen[size_t(id - 1)])
      throw InputError(path + ": atom id " + w[ci] + " is not one of the deck's");
    seen[size_t(id - 1)] = true;
    a[size_t(id - 1)] = {std::strtod(w[cx].c_str(), nullptr), std::strtod(w[cy].c_str(), nullptr),
                         std::strtod(w[cvx].c_str(), nullptr), std::strtod(w[cvy].c_str(), nullptr)};
  }
  return a;
}

namespace {

// A dump drawn by --from-dump: the atoms.txt its deck was written with, if it
// lies beside it, must be this scene's (same grains, same order of creation).
void check_atoms_beside(const std::string& dump, const LammpsDeck& deck) {
  const std::string path = (fs::path(dump).parent_path() / "atoms.txt").string();
  std::ifstream in(path);
  if (!in) return;
  std::stringstream text;
  text << in.rdbuf();
  if (text.str() != atoms_text(deck))
    throw InputError(path + ": the deck beside " + dump + " was not written for this scene (another scene, seed, "
                            "scale or --lammps-stiffness)");
}

// The deepest overlap between two grains at rest (px), by a grid of cells
// one large diameter wide.
double deepest_overlap(const std::vector<float>& x, const std::vector<float>& y, const std::vector<double>& r,
                       double cell, int W, int H) {
  const int cw = int(W / cell) + 2, ch = int(H / cell) + 2;
  std::vector<std::vector<int32_t>> grid(size_t(cw) * size_t(ch));
  auto at = [&](double v, int n) { return std::clamp(int(v / cell), 0, n - 1); };
  for (size_t i = 0; i < x.size(); ++i) grid[size_t(at(y[i], ch)) * cw + size_t(at(x[i], cw))].push_back(int32_t(i));
  double deepest = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const int gx = at(x[i], cw), gy = at(y[i], ch);
    for (int yy = std::max(0, gy - 1); yy <= std::min(ch - 1, gy + 1); ++yy)
      for (int xx = std::max(0, gx - 1); xx <= std::min(cw - 1, gx + 1); ++xx)
        for (int32_t j : grid[size_t(yy) * cw + size_t(xx)])
          if (size_t(j) > i) {
            const double dx = x[i] - x[size_t(j)], dy = y[i] - y[size_t(j)];
            deepest = std::max(deepest, r[i] + r[size_t(j)] - std::sqrt(dx * dx + dy * dy));
          }
  }
  return deepest;
}

class LammpsSimulator : public Simulator {
 public:
  explicit LammpsSimulator(LammpsOptions opt) : opt_(std::move(opt)) {}

  SimResult simulate(const SimInput& in, Progress& progress) override {
    if (in.frames.wanted())
      throw InputError("--frames and --video are not available in mode lammps (its grains are read back once, at the end)");
    const LammpsDeck deck = lammps_deck(in, opt_.stiffness);
    ordered_json st{{"engine", "LAMMPS (pair_style granular)"}};
    std::string dump = opt_.from_dump;
    Folder folder;
    std::string version;
    int64_t last_step = 0;
    if (dump.empty()) {
      if (opt_.folder.empty()) {
        std::string tmpl = (fs::temp_directory_path() / "sandpic-lammps-XXXXXX").string();
        if (!mkdtemp(tmpl.data())) throw InputError("cannot make a temporary folder in " + fs::temp_directory_path().string());
        folder.path = tmpl, folder.temporary = true;
      } else {
        check_folder(opt_.folder);
        folder.path = opt_.folder;
      }
      write_atomic(folder.path + "/atoms.txt", atoms_text(deck));
      try {
        const LammpsRun run = run_lammps(deck.input, folder.path, opt_, progress, deck.expected_steps);
        version = run.version, last_step = run.steps;
      } catch (const SimulationError&) {
        folder.temporary = false;  // kept for the user to read
        throw;
      }
      dump = folder.path + "/final.dump";
      st["folder"] = folder.temporary ? ordered_json() : ordered_json(folder.path);
    }
    if (!opt_.from_dump.empty()) check_atoms_beside(dump, deck);
    const std::vector<DumpAtom> atoms = read_lammps_dump(dump, deck.grain_of_atom.size());
    const Scene& s = in.scene;
    const int W = s.window.width, H = s.window.height;
    const auto radius = dem_radii(s);
    SimResult out;
    const size_t n = size_t(in.grains.size());
    out.x.assign(n, NAN);
    out.y.assign(n, NAN);
    std::vector<double> r(n, 0);
    double vmax = 0;
    for (size_t a = 0; a < atoms.size(); ++a) {
      const int32_t id = deck.grain_of_atom[a];
      const double rk = radius[in.grains.cls[size_t(id)]];
      const DumpAtom& p = atoms[a];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.vx) || !std::isfinite(p.vy) ||
          p.x < -rk || p.x > W + rk || p.y < -rk || p.y > H + rk)
        throw SimulationError("LAMMPS diverged: grain " + std::to_string(id) + " ended at (" + std::to_string(p.x) + ", " +
                              std::to_string(p.y) + ") px, outside the window");
      out.x[size_t(id)] = float(p.x);
      out.y[size_t(id)] = float(H - p.y);
      r[size_t(id)] = rk;
      vmax = std::max(vmax, std::hypot(p.vx, p.vy));
    }
    const double big = *std::max_element(radius.begin(), radius.end());
    const double small = *std::min_element(radius.begin(), radius.end());
    const double deepest = deepest_overlap(out.x, out.y, r, 2 * big, W, H);
    std::vector<uint8_t> cls(in.grains.cls.begin(), in.grains.cls.end());
    out.class_map = class_map_from_grains(W, H, out.x, out.y, cls, 1.2, kNoSand);
    st["lammps_version"] = version.empty() ? ordered_json() : ordered_json(version);
    st["ranks"] = opt_.from_dump.empty() ? ordered_json(opt_.launcher.empty() ? opt_.ranks : 0) : ordered_json();
    st["launcher"] = opt_.launcher.empty() ? ordered_json() : ordered_json(opt_.launcher);
    st["from_dump"] = opt_.from_dump.empty() ? ordered_json() : ordered_json(opt_.from_dump);
    st["stiffness_factor"] = opt_.stiffness;
    st["steps"] = last_step;
    st["simulated_s"] = double(last_step) * deck.contact.dt;
    const ordered_json figures = deck_json(deck);
    for (auto& [k, v] : figures.items()) st[k] = v;
    st["settled"] = vmax < deck.settle_speed_px_s;
    st["fastest_end_px_s"] = vmax;
    st["deepest_overlap_px"] = deepest;
    st["deepest_overlap_diameters"] = deepest / (2 * small);
    out.stats = st;
    return out;
  }

  Cost cost(const Scene& s) const override {
    // Measured: 0.12-0.2 µs per atom-step on one core, about 0.7 of the
    // grains in the window on average, 2 s of fall and settling after the
    // release (the default scene at --scale 0.1: 190-400 s).
    GrainSet g;
    g.width = s.window.width, g.height = s.region.height;
    g.cls.assign(size_t(g.size()), 0);
    const LammpsContact c = lammps_contact(s, g);
    const double n = double(g.size()), t = n / s.dem.release_rate + 2;
    return {n * 1000.0, t / c.dt * 0.7 * n * 0.2e-6 / std::max(1, opt_.ranks)};
  }

 private:
  LammpsOptions opt_;
};

}  // namespace

LammpsRun run_lammps(const std::string& input, const std::string& folder, const LammpsOptions& opt, Progress& progress,
                     int64_t total_steps) {
  const std::string lmp = find_lmp(opt);
  if (lmp.empty()) throw key_error("mode", "'lammps' needs LAMMPS's `" + opt.lmp + "` (apt-get install lammps, or scripts/setup.sh)");
  write_atomic(folder + "/in.sandpic", input);
  std::error_code ec;
  fs::remove(folder + "/final.dump", ec);  // never read a dump of an earlier run
  std::vector<std::string> argv;
  if (!opt.launcher.empty()) argv = words(opt.launcher);
  else if (opt.ranks > 1) argv = {"mpirun", "-np", std::to_string(opt.ranks)};
  argv.push_back(lmp);
  for (const char* a : {"-in", "in.sandpic", "-log", "log.lammps", "-nocite"}) argv.emplace_back(a);
  progress.start("lammps", total_steps);
  std::vector<std::string> tail;
  std::string error;
  LammpsRun run;
  Child child(argv, folder);
  for (std::string l; child.line(l);) {
    if (l.rfind("LAMMPS (", 0) == 0) run.version = l.substr(8, l.find(')') - 8);
    if (l.rfind("ERROR", 0) == 0 && error.empty()) error = l;
    const auto w = words(l);
    if (w.size() == 4 && std::all_of(w[0].begin(), w[0].end(), ::isdigit)) {
      run.steps = std::atoll(w[0].c_str());
      progress.update(std::min(run.steps, total_steps));  // the settle may run past the expected end
    }
    tail.push_back(l);
    if (tail.size() > 5) tail.erase(tail.begin());
  }
  const int rc = child.wait();
  progress.finish();
  if (rc != 0 || !fs::exists(folder + "/final.dump")) {
    std::string why = error.empty() ? (tail.empty() ? "no output" : tail.back()) : error;
    if (rc == 127 && error.empty()) why = "could not run " + argv.front();
    throw SimulationError("LAMMPS stopped (exit " + std::to_string(rc) + "): " + why + "; its log: " + folder +
                          "/log.lammps");
  }
  return run;
}

namespace {

std::string on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && access((d + "/" + name).c_str(), X_OK) == 0) return d + "/" + name;
  return "";
}

}  // namespace

std::string find_lmp(const LammpsOptions& opt) {
  if (opt.lmp.find('/') != std::string::npos) return access(opt.lmp.c_str(), X_OK) == 0 ? opt.lmp : "";
  return on_path(opt.lmp);
}

std::unique_ptr<Simulator> make_lammps_simulator(const LammpsOptions& opt) {
  return std::make_unique<LammpsSimulator>(opt);
}

ordered_json export_lammps(const SimInput& in, const std::string& folder) {
  const LammpsDeck deck = lammps_deck(in);
  check_folder(folder);
  write_atomic(folder + "/in.sandpic", deck.input);
  write_atomic(folder + "/atoms.txt", atoms_text(deck));
  write_atomic(folder + "/run.sh", run_script(deck));
  write_atomic(folder + "/deck.json", deck_json(deck).dump(2) + "\n");
  fs::permissions(folder + "/run.sh", fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                  fs::perm_options::add);
  return deck_json(deck);
}

}  // namespace sandpic
