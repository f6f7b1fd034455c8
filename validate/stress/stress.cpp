// The stress catalogue. Each case is a scene file (and the images
// it names) written into its own folder and rendered by a child sandpic, so
// the exit code, the one-line error and the files left behind are exactly
// what a user would get.
#include "validate/stress/stress.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/partitioner.h>
#include <tbb/parallel_for.h>


#include "src/errors.h"
#include "src/image_io.h"
#include "src/output.h"
#include "src/scene_file.h"

extern char** environ;

namespace sandpic {
namespace {

using ojson = nlohmann::ordered_json;
const std::set<Outcome> kAnyEnd = {Outcome::Picture, Outcome::Error, Outcome::Divergence};
const std::set<Outcome> kPicture = {Outcome::Picture};
const std::set<Outcome> kError = {Outcome::Error};

// "physics.friction" = v in a nested scene object.
void set_path(ojson& doc, const std::string& path, const ojson& v) {
  ojson* node = &doc;
  std::string rest = path;
  for (size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1)) node = &(*node)[rest.substr(0, dot)];
  (*node)[rest] = v;
}

// The catalogue's base: the default scene made small (2,000 grains quick,
// 7,950 full), written out whole so a case's file stands on its own.
ojson base_scene(bool quick) {
  Scene s;
  apply_scale(s, quick ? 0.1 : 0.15);  // smaller would make init.row_height_min < 1 px
  if (quick) s.region.height = 20;
  return to_json(s);
}

std::string dumped(const ojson& doc) { return doc.dump(2) + "\n"; }

// A case's scene file as a mode runs it. The catalogue's scenes are 15-20
// grains high and lie almost wholly inside three-layer's default band of
// static bodies (ten grains): its fixed layer and ground would hardly ever
// be reached, and the DEM cases would cost all-dynamic's work (the quick
// catalogue took 3,165 s with it, density-100:1 alone 1,705 s;
// docs/notebook/2026-12-07-the-band-counts-in-grains.md). One grain of band
// runs every layer's path. Only in the DEM's file: the lattice warns of a
// key it does not read, and a case's file that is not JSON stays as it is.
std::string mode_scene(const std::string& scene, const std::string& mode) {
  if (mode != "dem") return scene;
  ojson doc = ojson::parse(scene, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return scene;
  set_path(doc, "dem.static_thickness_diameters", 1);
  return dumped(doc);
}

// A number for a table or a label; "—" for a figure a run did not report (< 0).
std::string fixed(double v, const char* format) {
  if (v < 0) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// A case that sets keys of the base scene.
StressCase keys(std::string name, std::string about, std::vector<std::pair<std::string, ojson>> settings, bool quick,
                std::vector<std::string> modes = {"lattice", "dem"}, std::set<Outcome> expect = kAnyEnd) {
  StressCase c;
  c.name = std::move(name);
  c.about = std::move(about);
  c.modes = std::move(modes);
  c.expect = std::move(expect);
  c.scene = [quick, settings](const std::string&) {
    ojson doc = base_scene(quick);
    for (const auto& [path, v] : settings) set_path(doc, path, v);
    return dumped(doc);
  };
  return c;
}

// A halftone scene of `image`, written by `make` into the case's folder.
StressCase image_case(std::string name, std::string about, std::function<void(const std::string&)> make, bool quick,
                      std::set<Outcome> expect = kPicture) {
  StressCase c = keys(std::move(name), std::move(about), {}, quick, {"lattice", "dem"}, std::move(expect));
  c.scene = [quick, make](const std::string& dir) {
    ojson doc = base_scene(quick);
    set_path(doc, "init.method", "halftone");
    set_path(doc, "init.image", "input.png");
    if (make) make(dir + "/input.png");
    return dumped(doc);
  };
  c.mention = "input.png";
  return c;
}

// A scene file of exactly this text: bad input, read in the lattice mode
// (the file is refused before a backend is chosen).
StressCase text_case(std::string name, std::string about, std::string text, std::string mention) {
  StressCase c;
  c.name = std::move(name);
  c.about = std::move(about);
  c.modes = {"lattice"};
  c.expect = kError;
  c.mention = std::move(mention);
  c.scene = [text](const std::string&) { return text; };
  return c;
}

// A gradient, so the halftone has all four classes to make.
cv::Mat gradient(int w, int h, int type) {
  cv::Mat img(h, w, type);
  const int channels = img.channels();
  const double top = CV_MAT_DEPTH(type) == CV_16U ? 65535 : 255;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int ch = 0; ch < channels; ++ch) {
        double v = top * (x + y * 0.5) / (w + h * 0.5);
        if (ch == 3) v = top * 0.5;  // alpha: half
        if (CV_MAT_DEPTH(type) == CV_16U) img.ptr<uint16_t>(y)[x * channels + ch] = uint16_t(v);
        else img.ptr<uint8_t>(y)[x * channels + ch] = uint8_t(v);
      }
  return img;
}

void write_image(const std::string& path, const cv::Mat& img) {
  const std::vector<uchar> png = encode_picture(".png", img);
  write_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace

std::string outcome_name(Outcome o) {
  switch (o) {
    case Outcome::Picture: return "picture";
    case Outcome::Error: return "error (exit 2)";
    case Outcome::Divergence: return "divergence (exit 3)";
    case Outcome::Fail: return "FAIL";
  }
  return "?";
}

std::vector<StressCase> stress_cases(bool quick) {
  const ojson base = base_scene(quick);
  const int W = base["window"]["width"], H = base["window"]["height"], R = base["region"]["height"];
  std::vector<StressCase> cs;
  // paper §7's physics at and past its ends.
  cs.push_back(keys("friction-0", "physics.friction = 0", {{"physics.friction", 0}}, quick));
  cs.push_back(keys("friction-1.5", "physics.friction = 1.5", {{"physics.friction", 1.5}}, quick));
  cs.push_back(keys("restitution-0", "physics.restitution = 0", {{"physics.restitution", 0}}, quick));
  cs.push_back(keys("restitution-1", "physics.restitution = 1 (elastic)", {{"physics.restitution", 1}}, quick));
  // Grain size: at the scene's pixel size (sub-pixel grains; grains of many
  // pixels, one a pixel of the region, overfill the window) and with the
  // pixel scaled along (grains ~1.1 px, as by default: the physics alone
  // changes, settling speeds 10^5 apart).
  const double mm_px = base["units"]["mm_per_pixel"];
  cs.push_back(keys("grains-0.01mm", "grains.diameter_mm = 0.01 (all classes; " + fixed(0.01 / mm_px, "%.3g") + " px)",
                    {{"grains.diameter_mm", {0.01, 0.01, 0.01, 0.01}}}, quick));
  cs.push_back(keys("grains-0.01mm-1px", "grains.diameter_mm = 0.01, units.mm_per_pixel = 0.009",
                    {{"grains.diameter_mm", {0.01, 0.01, 0.01, 0.01}}, {"units.mm_per_pixel", 0.009}}, quick));
  cs.push_back(keys("grains-5mm", "grains.diameter_mm = 5 (all classes; " + fixed(5 / mm_px, "%.3g") + " px)",
                    {{"grains.diameter_mm", {5, 5, 5, 5}}}, quick));
  cs.push_back(keys("grains-5mm-1px", "grains.diameter_mm = 5, units.mm_per_pixel = 4.5",
                    {{"grains.diameter_mm", {5, 5, 5, 5}}, {"units.mm_per_pixel", 4.5}}, quick));
  cs.push_back(keys("density-100:1", "grains.density_g_cm3 = [1.05, 1.05, 100, 100] (in water of 1.0)",
                    {{"grains.density_g_cm3", {1.05, 1.05, 100, 100}}}, quick));
  cs.push_back(keys("step-x10", "dem.step_diameters = 0.5 (10x the default time step)", {{"dem.step_diameters", 0.5}},
                    quick, {"dem"}));
  {
    // Without the stiffness watch's sub-steps, and a divergence limit that
    // twenty times the default step passes (the contacts hold at 10x now:
    // 0.27 small diameters deep at the most): the run must stop itself with
    // a report, not write a picture of grains sunk into each other.
    StressCase c = keys("step-x20-no-substeps", "dem.step_diameters = 1, dem.max_substeps = 1, dem.max_overlap = 0.1",
                        {{"dem.step_diameters", 1}, {"dem.max_substeps", 1}, {"dem.max_overlap", 0.1}}, quick, {"dem"},
                        {Outcome::Divergence});
    c.mention = "dem.step_diameters";
    cs.push_back(c);
  }
  cs.push_back(keys("step-div10", "dem.step_diameters = 0.005 (a tenth of the default time step)",
                    {{"dem.step_diameters", 0.005}}, quick, {"dem"}));
  // Size: millions of grains; the DEM's estimate refuses before starting.
  {
    StressCase c = keys("millions", "window 2400x1800, region 1200 px: 2.88 million grains",
                        {{"window.width", 2400}, {"window.height", 1800}, {"region.height", 1200}}, quick);
    c.args = {"--max-hours", "2"};
    cs.push_back(c);
  }
  {
    StressCase c = keys("memory-limit", "window 20000x20000, region 16000 px: 320 million grains, --max-memory-gb 8",
                        {{"window.width", 20000}, {"window.height", 20000}, {"region.height", 16000}}, quick,
                        {"lattice", "dem"}, kError);
    c.args = {"--max-memory-gb", "8"};
    c.mention = "memory";
    cs.push_back(c);
  }
  // The initialization region at its ends.
  cs.push_back(keys("region-1px", "region.height = 1", {{"region.height", 1}}, quick));
  cs.push_back(keys("region-full", "region.height = window.height (" + std::to_string(H) + " px; its sand overfills it)",
                    {{"region.height", H}}, quick));
  cs.push_back(keys("region-full-fine", "region.height = window.height, grains 0.6 and 0.4 px so that their sand fits",
                    {{"region.height", H}, {"grains.diameter_mm", {0.6 * mm_px, 0.6 * mm_px, 0.4 * mm_px, 0.4 * mm_px}}},
                    quick));
  // Ellipses (§5): round, needle-thin, overlapping, reaching out of the region.
  cs.push_back(keys("eccentricity-0", "segment.eccentricity_min = max = 0",
                    {{"segment.eccentricity_min", 0}, {"segment.eccentricity_max", 0}}, quick));
  // Semi-major axes of 0.4 window widths: at 0.999 the ellipses are 0.045
  // as high as wide, and smaller ones would be under 0.5 px (refused).
  cs.push_back(keys("eccentricity-0.999", "segment.eccentricity_min = max = 0.999, semi-major axes 0.4 window widths",
                    {{"segment.eccentricity_min", 0.999}, {"segment.eccentricity_max", 0.999},
                     {"segment.semi_major_min", 0.4 * W}, {"segment.semi_major_max", 0.4 * W}}, quick));
  const double cx = W / 2.0, cy = R / 2.0;
  cs.push_back(keys("ellipses-overlapping", "segment.method = explicit, two ellipses sharing most of their area",
                    {{"segment.method", "explicit"},
                     {"segment.ellipses",
                      {{{"cx", cx - 4}, {"cy", cy}, {"a", W / 3.0}, {"b", R / 3.0}, {"angle_deg", 0}},
                       {{"cx", cx + 4}, {"cy", cy + 2}, {"a", W / 3.0}, {"b", R / 2.5}, {"angle_deg", 10}}}}},
                    quick));
  cs.push_back(keys("ellipses-outside", "segment.method = explicit, ellipses reaching out of the region and window",
                    {{"segment.method", "explicit"},
                     {"segment.ellipses",
                      {{{"cx", 0}, {"cy", R}, {"a", W / 2.0}, {"b", R}, {"angle_deg", 0}},
                       {{"cx", W + 10.0}, {"cy", -5}, {"a", W / 3.0}, {"b", R / 2.0}, {"angle_deg", 30}}}}},
                    quick));
  // Input pictures (§4.2): any size is resized to the region, any depth or
  // channel count read as 8-bit colour; unreadable ones are named.
  cs.push_back(image_case("image-1x1", "init.image 1x1 px", [](const std::string& p) {
    write_image(p, cv::Mat(1, 1, CV_8UC3, cv::Scalar(40, 120, 200)));
  }, quick));
  cs.push_back(image_case("image-16bit", "init.image 16-bit colour PNG", [W, R](const std::string& p) {
    write_image(p, gradient(W, R, CV_16UC3));
  }, quick));
  cs.push_back(image_case("image-grey", "init.image 8-bit greyscale PNG", [W, R](const std::string& p) {
    write_image(p, gradient(W, R, CV_8UC1));
  }, quick));
  cs.push_back(image_case("image-alpha", "init.image RGBA PNG (alpha ignored)", [W, R](const std::string& p) {
    write_image(p, gradient(W, R, CV_8UC4));
  }, quick));
  cs.push_back(image_case("image-wrong-size", "init.image 7 times wider and a third as high as the region (resized)",
                          [W, R](const std::string& p) { write_image(p, gradient(7 * W, std::max(1, R / 3), CV_8UC3)); },
                          quick));
  cs.push_back(image_case("image-corrupt", "init.image a PNG cut after its header", [](const std::string& p) {
    const std::vector<uchar> png = encode_png(gradient(64, 64, CV_8UC3));
    write_atomic(p, std::string_view(reinterpret_cast<const char*>(png.data()), 40));
  }, quick, kError));
  cs.push_back(image_case("image-missing", "init.image names no file", nullptr, quick, kError));
  // Scene files a person might write by mistake.
  cs.push_back(text_case("json-malformed", "a comma missing at the end of line 2",
                         "{\n  \"window\": {\"width\": 100, \"height\": 70}\n  \"region\": {\"height\": 20}\n}\n", "line 3"));
  cs.push_back(text_case("json-nan", "physics.friction = NaN", R"({"physics": {"friction": NaN}})", "line 1"));
  cs.push_back(text_case("json-infinity", "physics.friction = 1e999", R"({"physics": {"friction": 1e999}})",
                         "physics.friction"));
  cs.push_back(text_case("wrong-type", "window.width = \"wide\"", R"({"window": {"width": "wide"}})", "window.width"));
  cs.push_back(text_case("negative-size", "region.height = -5", R"({"region": {"height": -5}})", "region.height"));
  cs.push_back(text_case("absurd-size", "window.width = 1e12", R"({"window": {"width": 1e12}})", "window.width"));
  cs.push_back(text_case("unknown-key", "physics.frction (a typo)", R"({"physics": {"frction": 0.4}})", "physics.frction"));
  return cs;
}

ChildRun run_child(const std::vector<std::string>& argv, const std::string& out_file, const std::string& err_file,
                   double timeout_s) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int failed = posix_spawn(&pid, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (failed) throw SimulationError("stress: cannot start " + argv[0]);
  ChildRun run;
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == pid) break;
    if (run.seconds > timeout_s) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      run.timed_out = true;
      return run;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(run.seconds < 1 ? 5 : 50));
  }
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  return run;
}

namespace {

// Every number of the stats finite: nlohmann writes a NaN or an infinity as
// null, so a null anywhere is one.
bool all_finite(const nlohmann::json& j) {
  if (j.is_null()) return false;
  if (j.is_number_float()) return std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const auto& v : j)
      if (!all_finite(v)) return false;
  return true;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

double number_or(const nlohmann::json& j, const char* key, double fallback) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

}  // namespace

StressRow judge(const StressCase& c, const std::string& mode, const ChildRun& run, const StressFiles& f) {
  StressRow row;
  row.name = c.name, row.about = c.about, row.mode = mode;
  row.exit_code = run.exit_code;
  row.seconds = run.seconds;
  auto fail = [&](const std::string& why) {
    row.outcome = Outcome::Fail;
    row.message = why;
    return row;
  };
  if (run.timed_out) return fail("no end within the time limit (a hang?)");
  if (run.signal) return fail("killed by signal " + std::to_string(run.signal) + " (a crash)");
  const std::vector<std::string> err = lines_of(read_text(f.err).value_or(""));
  if (run.exit_code == 0) {
    const auto stats_text = read_text(f.stats);
    if (!stats_text) return fail("exit 0 without stats");
    nlohmann::json st;
    try {
      st = nlohmann::json::parse(*stats_text);
    } catch (const nlohmann::json::exception&) {
      return fail("exit 0 with unreadable stats");
    }
    if (!all_finite(st)) return fail("a NaN or infinity in the stats");
    const cv::Mat pic = read_picture(f.picture, ImageRead::Unchanged);
    if (pic.empty()) return fail("exit 0 without a readable picture");
    if (pic.cols != st["window"][0].get<int>() || pic.rows != st["window"][1].get<int>())
      return fail("the picture is not the window's size");
    const auto& g = st["grains"];
    row.released = g["released"], row.in_picture = g["in_picture"];
    if (row.released != g["total"].get<int64_t>() || row.in_picture != row.released)
      return fail("grains not accounted for: " + std::to_string(row.in_picture) + " in the picture of " +
                  std::to_string(row.released) + " released");
    const auto& b = st["backend"];
    row.overlap_px = number_or(b, "deepest_overlap_px", -1);
    row.overlap_diameters = number_or(b, "deepest_overlap_diameters", -1);
    row.kinetic_energy_j = number_or(b, "kinetic_energy_end_J", -1);
    row.substeps = int(number_or(b, "substeps", 0));
    row.outcome = Outcome::Picture;
  } else if (run.exit_code == 2 || run.exit_code == 3) {
    row.message = err.empty() ? "" : err.front();
    if (err.size() != 1) return fail("exit " + std::to_string(run.exit_code) + " with " + std::to_string(err.size()) +
                                     " lines on stderr, not one");
    if (!c.mention.empty() && row.message.find(c.mention) == std::string::npos)
      return fail("the error does not name '" + c.mention + "': " + row.message);
    if (read_text(f.picture) != f.sentinel) return fail("the earlier picture was overwritten or removed");
    if (std::filesystem::exists(f.stats)) return fail("stats were written for a failed run");
    row.outcome = run.exit_code == 2 ? Outcome::Error : Outcome::Divergence;
  } else {
    return fail("exit code " + std::to_string(run.exit_code));
  }
  if (!c.expect.count(row.outcome)) {
    std::string want;
    for (Outcome o : c.expect) want += (want.empty() ? "" : " or ") + outcome_name(o);
    return fail(outcome_name(row.outcome) + " where " + want + " was expected" +
                (row.message.empty() ? "" : ": " + row.message));
  }
  return row;
}

std::vector<StressRow> run_stress(const StressOptions& opt, const std::function<void(const StressRow&)>& done) {
  // A hang is a run with no end: the limit sits well above the slowest
  // case's honest time (quick: density-100:1, 346-506 s for the same work
  // on this machine with three-layer's band of static bodies, 230 s with
  // immovable static grains). The full catalogue's limit is as long.
  const double timeout = opt.timeout_s > 0 ? opt.timeout_s : 1800;
  const std::vector<StressCase> cases = stress_cases(opt.quick);
  struct Task {
    const StressCase* c;
    std::string mode;
  };
  std::vector<Task> tasks;
  for (const StressCase& c : cases) {
    if (!opt.only.empty() && std::find(opt.only.begin(), opt.only.end(), c.name) == opt.only.end()) continue;
    for (const std::string& mode : c.modes)
      if (mode != "dem" || opt.with_dem) tasks.push_back({&c, mode});
  }
  auto run_one = [&](const Task& t) {
    const StressCase& c = *t.c;
    const std::string dir = opt.out + "/cases/" + c.name + "-" + t.mode;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    write_atomic(dir + "/scene.json", mode_scene(c.scene(dir), t.mode));
    // A picture from an earlier render: a failed run must leave it as it is.
    StressFiles f{dir + "/picture.png", dir + "/stats.json", dir + "/stderr.txt",
                  "an earlier picture of " + c.name + "\n"};
    write_atomic(f.picture, f.sentinel);
    std::vector<std::string> argv = {opt.exe, "render", dir + "/scene.json", "--mode", t.mode, "-o", f.picture,
                                     "--stats", f.stats};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    const ChildRun run = run_child(argv, dir + "/stdout.txt", f.err, timeout);
    return judge(c, t.mode, run, f);
  };
  // Runs side by side on TBB's threads, each a child process in a folder of
  // its own: a DEM run is one world on one core, and run one at a time the
  // quick catalogue left the second core idle for 20 minutes of CI. The rows
  // keep the catalogue's order whatever order the runs end in; an error
  // starting a child cancels the runs not yet started and is rethrown.
  std::unique_ptr<tbb::global_control> threads;
  if (opt.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(opt.threads));
  std::vector<StressRow> rows(tasks.size());
  std::mutex m;
  // One run a task (simple_partitioner, grain 1): a run can take 2 s or 10
  // minutes, and a chunk of neighbouring cases run on one thread held the
  // quick catalogue's two longest (density-100:1, step-div10) one after the
  // other while the second core sat idle.
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, tasks.size(), 1),
      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          rows[i] = run_one(tasks[i]);
          std::lock_guard<std::mutex> lock(m);
          if (done) done(rows[i]);
        }
      },
      tbb::simple_partitioner());
  return rows;
}

namespace {

std::string cell(std::string text) {  // a Markdown table cell
  std::replace(text.begin(), text.end(), '|', '/');
  if (text.size() > 140) text.resize(137), text += "...";
  return text;
}

}  // namespace

std::string stress_markdown(const std::vector<StressRow>& rows, const StressOptions& opt) {
  std::ostringstream md;
  int fails = 0;
  for (const StressRow& r : rows) fails += r.outcome == Outcome::Fail;
  md << "# sandpic stress" << (opt.quick ? " --quick" : "") << "\n\n"
     << rows.size() << " runs, " << fails << " failed. Overlap: the deepest between two grains in the DEM run, px "
     << "(small-grain diameters); KE: kinetic energy of the grains still moving at the end; — where the mode has "
     << "none (the lattice has cells, no bodies) or the run made no picture.\n\n"
     << "| case | mode | outcome | time s | grains in picture / released | overlap px (diam.) | KE end J | "
        "sub-steps | message |\n|---|---|---|---:|---:|---:|---:|---:|---|\n";
  for (const StressRow& r : rows) {
    md << "| " << r.name << " | " << r.mode << " | " << outcome_name(r.outcome) << " | " << fixed(r.seconds, "%.2f")
       << " | "
       << (r.released >= 0 ? std::to_string(r.in_picture) + " / " + std::to_string(r.released) : std::string("—"))
       << " | " << fixed(r.overlap_px, "%.3g")
       << (r.overlap_diameters >= 0 ? " (" + fixed(r.overlap_diameters, "%.2f") + ")" : std::string()) << " | "
       << fixed(r.kinetic_energy_j, "%.3g") << " | " << (r.substeps > 0 ? std::to_string(r.substeps) : "—") << " | "
       << cell(r.message) << " |\n";
  }
  md << "\nCases:\n\n";
  std::string last;
  for (const StressRow& r : rows)
    if (r.name != last) md << "- `" << r.name << "`: " << cell(r.about) << "\n", last = r.name;
  return md.str();
}

nlohmann::ordered_json stress_json(const std::vector<StressRow>& rows, const StressOptions& opt) {
  ojson out;
  out["quick"] = opt.quick;
  out["with_dem"] = opt.with_dem;
  ojson list = ojson::array();
  int fails = 0;
  for (const StressRow& r : rows) {
    fails += r.outcome == Outcome::Fail;
    auto maybe = [](double v) { return v < 0 ? ojson(nullptr) : ojson(v); };
    list.push_back({{"case", r.name},
                    {"about", r.about},
                    {"mode", r.mode},
                    {"outcome", outcome_name(r.outcome)},
                    {"exit_code", r.exit_code},
                    {"seconds", r.seconds},
                    {"grains_released", r.released >= 0 ? ojson(r.released) : ojson(nullptr)},
                    {"grains_in_picture", r.in_picture >= 0 ? ojson(r.in_picture) : ojson(nullptr)},
                    {"deepest_overlap_px", maybe(r.overlap_px)},
                    {"deepest_overlap_diameters", maybe(r.overlap_diameters)},
                    {"kinetic_energy_end_J", maybe(r.kinetic_energy_j)},
                    {"substeps", r.substeps},
                    {"message", r.message}});
  }
  out["runs"] = rows.size();
  out["failed"] = fails;
  out["rows"] = list;
  return out;
}

}  // namespace sandpic
