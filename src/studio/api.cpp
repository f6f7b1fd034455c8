#include "src/studio/api.h"

#include <filesystem>
#include <mutex>


#include "src/image_io.h"
#include "src/init/init.h"
#include "src/output.h"
#include "src/pipeline.h"
#include "src/segment/segment.h"

namespace sandpic::studio {

namespace fs = std::filesystem;

Reply error_reply(const std::string& message, int status) {
  Reply r;
  r.status = status;
  r.body = ordered_json{{"error", message}, {"key", key_of(message)}}.dump();
  return r;
}

Reply json_reply(const ordered_json& doc) {
  Reply r;
  r.body = doc.dump();
  return r;
}

std::string key_of(const std::string& message) {
  // The innermost key: "scene file 'x': scene key 'a.b': ..." names a.b.
  const std::string mark = "scene key '";
  const size_t at = message.find(mark);
  if (at == std::string::npos) return "";
  const size_t from = at + mark.size(), to = message.find('\'', from);
  return to == std::string::npos ? "" : message.substr(from, to - from);
}

void check_inside(const std::string& root, const std::string& path, const std::string& key) {
  if (path.empty()) return;
  const fs::path base = fs::weakly_canonical(fs::absolute(root));
  const fs::path p = fs::weakly_canonical(fs::absolute(base / path));
  const auto [b, _] = std::mismatch(base.begin(), base.end(), p.begin(), p.end());
  if (b != base.end()) throw key_error(key, "'" + path + "' is outside the studio's folder " + base.string());
}

namespace {

// Every file a scene may open, with its key: the studio reads none outside
// its working folder (a page could otherwise ask for any file on the machine).
void check_paths(const Scene& s, const std::string& root, const std::string& prefix = "") {
  check_inside(root, s.init.image, prefix + "init.image");
  check_inside(root, s.segment.sketch.image, prefix + "segment.sketch.image");
  check_inside(root, s.lattice.calibration, prefix + "lattice.calibration");
  check_inside(root, s.render.background, prefix + "render.background");
  for (size_t i = 0; i < s.render.figures.size(); ++i)
    check_inside(root, s.render.figures[i].mask, prefix + "render.figures[" + std::to_string(i) + "].mask");
}

// "localhost" from "localhost:8080", "::1" from "[::1]:8080".
std::string host_name(const std::string& host_port) {
  if (host_port.starts_with('[')) return host_port.substr(1, host_port.find(']') - 1);
  return host_port.substr(0, host_port.find(':'));
}

}  // namespace

bool is_loopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }

std::string refusal(const std::string& listen_host, const std::string& method, const std::string& host_header,
                    const std::string& origin) {
  if (!is_loopback(listen_host)) return "";
  if (!host_header.empty() && !is_loopback(host_name(host_header)))
    return "Host '" + host_header + "' is not this studio's address: open it as http://" + listen_host + ":PORT/";
  if (method != "GET" && method != "HEAD" && !origin.empty()) {
    const std::string scheme = "http://";
    if (!origin.starts_with(scheme) || !is_loopback(host_name(origin.substr(scheme.size()))))
      return "a request from the page of '" + origin + "' is refused: only the studio's own page may change it";
  }
  return "";
}

Scene scene_from_request(const std::string& body, const std::string& root) {
  if (body.size() > kMaxRequestBytes)
    throw TooLarge("request of " + std::to_string(body.size()) + " bytes is over the limit of " +
                     std::to_string(kMaxRequestBytes));
  Scene s = scene_from_text(body, "request", root);
  validate(s);
  check_paths(s, root);
  for (size_t i = 0; i < s.regions.size(); ++i)
    check_paths(area_scene(s, i), root, "regions[" + std::to_string(i) + "].");
  return s;
}

std::optional<double> number_of(const std::string& text) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size()) return std::nullopt;
  return v;
}

double scale_param(const std::string& text) {
  if (text.empty()) return 1;
  const auto v = number_of(text);
  if (!v || !(*v > 0 && *v <= 4)) throw InputError("scale: '" + text + "' is not a number in (0, 4]");
  return *v;
}

Scene scaled(Scene s, double scale) {
  if (scale == 1) return s;
  apply_scale(s, scale);
  validate(s);
  return s;
}

Reply upload_image(const std::string& bytes, const std::string& root) {
  if (bytes.size() > kMaxImageBytes)
    throw TooLarge("image of " + std::to_string(bytes.size()) + " bytes is over the limit of " +
                   std::to_string(kMaxImageBytes));
  const cv::Mat img = decode_picture(bytes.data(), bytes.size());
  if (img.empty()) throw InputError("image: not a picture OpenCV can read (PNG, JPEG, BMP, TIFF, WebP, ...)");
  if (double(img.total()) > kMaxImagePixels)
    throw InputError("image: " + std::to_string(img.cols) + " x " + std::to_string(img.rows) +
                     " px is over the limit of 50 megapixels; the region is a few hundred px high");
  const std::vector<uchar> png = encode_png(img);
  // FNV-1a of the picture: its name, so a picture dropped again is the same file.
  uint64_t h = 1469598103934665603ull;
  for (uchar b : png) h = (h ^ b) * 1099511628211ull;
  char name[48];
  std::snprintf(name, sizeof name, "image-%016llx.png", (unsigned long long)h);
  const std::string rel = std::string("studio-inputs/") + name;
  check_folder((fs::path(root) / "studio-inputs").string());
  write_atomic((fs::path(root) / rel).string(), std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
  return json_reply({{"path", rel}, {"width", img.cols}, {"height", img.rows}});
}

Reply scene_reply(const Scene& s) { return json_reply(to_json(s)); }

Reply complete_scene(const std::string& body, const std::string& root) {
  return scene_reply(scene_from_request(body, root));
}

Reply preview(const std::string& body, const std::string& root, double scale) {
  Scene s = scaled(scene_from_request(body, root), scale);
  s.mode = Mode::Lattice;  // a preview is always the lattice's; the DEM is the final render
  auto sim = make_simulator(s);
  // While a physics key is dragged, the layout (paper §4-6) is the last
  // preview's: only the fall is run again.
  static std::mutex kept_mutex;
  static std::string kept_key;
  static std::shared_ptr<const Prepared> kept;
  const std::string key = layout_key(s);
  RunOptions opt;
  // A preview is shown, not kept: the same pixels in a palette PNG, about a
  // fifth of the render's bytes, as fast to write and faster to decode.
  opt.palette_png = true;
  {
    std::lock_guard lock(kept_mutex);
    if (key == kept_key) opt.prepared = kept;
  }
  RunResult run = run_pipeline(s, *sim, opt);
  {
    std::lock_guard lock(kept_mutex);
    kept_key = key;
    kept = run.prepared;
  }
  Reply r;
  r.content_type = "image/png";
  r.body.assign(reinterpret_cast<const char*>(run.png.data()), run.png.size());
  r.headers["X-Sandpic-Stats"] = run.stats.dump();
  return r;
}

Reply units(const std::string& body, const std::string& root) {
  const Scene s = scene_from_request(body, root);
  const Initialization init = initialize(s);
  const Segmentation seg = segment(s, init.tessellation);
  ordered_json ellipses = ordered_json::array(), cells = ordered_json::array();
  for (const Unit& u : seg.units) {
    if (u.is_ellipse)
      ellipses.push_back({u.ellipse.c.x(), u.ellipse.c.y(), u.ellipse.a, u.ellipse.b, u.ellipse.theta});
    else
      cells.push_back({u.x0, u.y0, u.x1, u.y1});
  }
  // paper §3, "users may further edit colors in the cells": the scene's own
  // cells (not an area's, Fig. 17), numbered as init.cell_overrides counts
  // them, with the classes they hold (1-based, as in scene files).
  ordered_json tess = ordered_json::array();
  for (const Cell& c : init.tessellation.cells)
    if (c.area == 0) tess.push_back({c.x0, c.y0, c.x1, c.y1, c.dominant + 1, c.secondary + 1});
  return json_reply({{"ellipses", ellipses}, {"cells", cells}, {"tessellation", tess}});
}

}  // namespace sandpic::studio
