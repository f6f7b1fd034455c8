#include "validate/runs/kept_runs.h"

#include "src/image_io.h"
#include "src/output.h"
#include "src/scene_file.h"

namespace sandpic {

std::optional<KeptRun> load_kept(const std::string& dir, const std::string& label, const Scene& s) {
  if (dir.empty()) return std::nullopt;
  const std::string base = dir + "/" + label;
  const std::optional<std::string> text = read_text(base + ".json");
  if (!text) return std::nullopt;
  KeptRun r;
  r.stats = ordered_json::parse(*text, nullptr, false);
  if (r.stats.is_discarded() || !r.stats.is_object() || r.stats.value("scene_digest", "") != scene_digest(s))
    return std::nullopt;
  try {
    r.stats.at("timing").at("simulate_s").get<double>();
    r.stats.at("grains").at("total").get<int64_t>();
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const cv::Size window(s.window.width, s.window.height);
  r.picture = read_picture(base + ".png");
  if (r.picture.empty() || r.picture.size() != window) return std::nullopt;
  r.class_map = read_picture(base + ".classes.png", ImageRead::Grey);
  if (!r.class_map.empty() && r.class_map.size() != window) r.class_map.release();
  return r;
}

void keep_run(const std::string& dir, const std::string& label, const RunResult& r) {
  const std::string base = dir + "/" + label;
  auto bytes = [](const std::vector<uchar>& v) { return std::string_view(reinterpret_cast<const char*>(v.data()), v.size()); };
  const std::vector<uchar> classes = encode_png(r.class_map);
  write_atomic(base + ".png", bytes(r.png));
  write_atomic(base + ".classes.png", bytes(classes));
  // The stats last: a run counts as kept only once its pictures are.
  write_atomic(base + ".json", r.stats.dump(2) + "\n");
}

ReusedRun run_or_reuse(const std::string& dir, const std::string& label, const Scene& s, const SimulatorFactory& make,
                       bool need_class_map) {
  if (std::optional<KeptRun> kept = load_kept(dir, label, s))
    if (!need_class_map || !kept->class_map.empty()) return {std::move(*kept), true};
  auto sim = make(s);
  RunResult r = run_pipeline(s, *sim, RunOptions{});
  if (!dir.empty()) keep_run(dir, label, r);
  return {KeptRun{r.picture, r.class_map, std::move(r.stats)}, false};
}

}  // namespace sandpic
