#include "src/scene_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "src/errors.h"
#include "src/output.h"
#include "src/presets.h"
#include "src/rng.h"

namespace sandpic {
namespace {

// Removes "a.b.c" from j, and the objects it leaves empty.
void erase_path(ordered_json& j, const std::string& path) {
  const size_t dot = path.find('.');
  if (dot == std::string::npos) return void(j.erase(path));
  const std::string head = path.substr(0, dot);
  if (!j.contains(head)) return;
  erase_path(j[head], path.substr(dot + 1));
  if (j[head].empty()) j.erase(head);
}

bool is_prefix_of_a_field(const std::string& path) {
  for (auto& f : scene_fields())
    if (f.path.size() > path.size() && f.path.compare(0, path.size(), path) == 0 && f.path[path.size()] == '.')
      return true;
  return false;
}

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// nlohmann's parser copies values recursively, so a document nested some
// 100,000 levels deep overflows the stack: refused here, where the parser
// calls back at every level. A scene needs 8 (regions[i].segment.sketch.ridges[j][k]).
// `what` names the text in the error ("scene file 'a.json'").
constexpr int kMaxJsonDepth = 64;

json parse_nested(const std::string& text, bool allow_exceptions, const std::string& what) {
  return json::parse(
      text,
      [&what](int depth, json::parse_event_t, json&) {
        if (depth > kMaxJsonDepth)
          throw InputError(what + ": JSON nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
        return true;
      },
      allow_exceptions);
}

[[noreturn]] void unknown_key(const std::string& path) {
  throw InputError("unknown scene key '" + path + "' (did you mean '" + nearest_key(path) +
                   "'? `sandpic scene` lists every key)");
}

void apply_at(Scene& s, const std::string& path, const json& v) {
  if (const Field* f = find_field(path)) return f->set(s, v);
  if (v.is_object() && (path.empty() || is_prefix_of_a_field(path))) {
    for (auto& [k, child] : v.items()) apply_at(s, path.empty() ? k : path + "." + k, child);
    return;
  }
  unknown_key(path);
}

// "line L, column C" of a byte offset, for JSON syntax errors.
std::string where(const std::string& text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, col = 1;
    else ++col;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

// nlohmann refuses a number past a double's range (1e999) with an
// out_of_range error that says neither where nor which key; its SAX parser
// gives the byte it stopped at, and this one keeps the key path to it.
struct KeyPathSax : nlohmann::json_sax<json> {
  struct Level {
    bool array;
    long index;
    std::string key;
  };
  std::vector<Level> levels;
  size_t stopped_at = 0;
  std::string path() const {
    std::string p;
    for (const Level& l : levels)
      p += l.array ? "[" + std::to_string(l.index) + "]" : (p.empty() ? "" : ".") + l.key;
    return p;
  }
  bool value() {
    if (!levels.empty() && levels.back().array) ++levels.back().index;
    return true;
  }
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(size_t) override { return value(), levels.push_back({false, -1, ""}), true; }
  bool key(string_t& k) override { return levels.back().key = k, true; }
  bool end_object() override { return levels.pop_back(), true; }
  bool start_array(size_t) override { return value(), levels.push_back({true, -1, ""}), true; }
  bool end_array() override { return levels.pop_back(), true; }
  bool parse_error(size_t position, const std::string&, const nlohmann::detail::exception&) override {
    stopped_at = position;
    return false;
  }
};

// A non-negative size in px² as a whole number: long() is undefined past 2^63,
// which the largest grains on the finest pixels reach.
std::string whole(double v) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(0) << std::floor(v);
  return o.str();
}

json scaled(const json& v, double f, const std::string& path) {
  if (v.is_number_integer()) return json(static_cast<long long>(std::max(1.0, std::round(v.get<double>() * f))));
  if (v.is_number()) return json(v.get<double>() * f);
  if (v.is_array()) {
    json out = json::array();
    for (auto& e : v) out.push_back(scaled(e, f, path));
    return out;
  }
  if (v.is_object()) {  // an ellipse or a figure: positions, axes and sizes scale, an angle or a file does not
    json out = v;
    for (auto k : {"cx", "cy", "a", "b", "x", "y", "scale", "polygon"})
      if (v.contains(k)) out[k] = scaled(v[k], f, path);
    return out;
  }
  return v;
}

}  // namespace

const Field* find_field(const std::string& path) {
  for (auto& f : scene_fields())
    if (f.path == path) return &f;
  return nullptr;
}

std::string nearest_key(const std::string& path) {
  std::string best;
  size_t best_d = SIZE_MAX;
  for (auto& f : scene_fields()) {
    // Compare with the whole path and with its last part, so that a bare
    // "friction" still finds "physics.friction".
    std::string leaf = f.path.substr(f.path.rfind('.') + 1);
    size_t d = std::min(edit_distance(path, f.path), edit_distance(path, leaf));
    if (d < best_d) best_d = d, best = f.path;
  }
  return best;
}

void apply_json(Scene& s, const json& doc) {
  if (!doc.is_object()) throw InputError("a scene file holds one JSON object, got " + std::string(doc.type_name()));
  // paper §9: a preset is a base, so it is read before the keys that override it.
  if (doc.contains("preset")) apply_at(s, "preset", doc["preset"]);
  for (auto& [k, child] : doc.items())
    if (k != "preset") apply_at(s, k, child);
}

std::string with_path_prefix(const InputError& e, const std::string& prefix) {
  std::string m = e.what();
  const std::string head = "scene key '";
  if (m.rfind(head, 0) == 0) m.insert(head.size(), prefix + ".");
  else m = prefix + ": " + m;
  return m;
}

Scene area_scene(const Scene& s, size_t i) {
  const Area& a = s.regions.at(i);
  Scene out = s;
  out.regions.clear();
  const std::string where = "regions[" + std::to_string(i) + "]";
  try {
    if (!a.preset.empty()) {  // only the keys an area may set
      json doc = json::parse(find_preset(a.preset)->json), part = json::object();
      for (const char* k : {"init", "segment"})
        if (doc.contains(k)) part[k] = doc[k];
      if (doc.contains("grains") && doc["grains"].contains("proportions"))
        part["grains"]["proportions"] = doc["grains"]["proportions"];
      apply_json(out, part);
    }
    for (auto& [path, text] : a.settings) find_field(path)->set(out, json::parse(text));
  } catch (const InputError& e) {
    throw InputError(with_path_prefix(e, where));
  }
  // Its own layout: two areas with one tessellation kind are not copies.
  out.layout_seed = key(s.layout(), Stream::Area, i);
  return out;
}

Scene scene_from_text(const std::string& text, const std::string& name, const std::string& base_dir) {
  json doc;
  try {
    doc = parse_nested(text, true, "scene file '" + name + "'");
  } catch (const json::parse_error& e) {
    // nlohmann's reason follows "... while parsing <what> - ".
    const std::string what = e.what(), reason = what.substr(std::min(what.size(), what.find(" - ") + 3));
    throw InputError("scene file '" + name + "': malformed JSON at " + where(text, e.byte > 0 ? e.byte - 1 : 0) +
                     (reason.empty() ? "" : ": " + reason));
  } catch (const json::out_of_range&) {  // a number past a double's range
    KeyPathSax sax;
    json::sax_parse(text, &sax);
    throw InputError("scene file '" + name + "': scene key '" + sax.path() + "': a number too large for a double, at " +
                     where(text, sax.stopped_at > 0 ? sax.stopped_at - 1 : 0));
  }
  Scene s;
  s.base_dir = base_dir;
  try {
    apply_json(s, doc);
  } catch (const InputError& e) {
    throw InputError("scene file '" + name + "': " + e.what());
  }
  return s;
}

Scene load_scene(const std::string& path) {
  const std::optional<std::string> read = read_text(path);
  if (!read) throw InputError("cannot read scene file '" + path + "'");
  size_t slash = path.rfind('/');
  return scene_from_text(*read, path, slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash));
}

void apply_setting(Scene& s, const std::string& assignment) {
  size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set expects key.path=value, got '" + assignment + "'");
  std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  json v = parse_nested(text, false, "scene key '" + path + "'");
  if (v.is_discarded()) v = text;  // a bare word is a string: --set mode=lattice
  if (!find_field(path)) unknown_key(path);
  find_field(path)->set(s, v);
}

// Every length in pixels is multiplied by `factor`, so the grain count goes by
// factor². Grains keep their size in pixels: a pixel (and so every mm value)
// grows by 1/factor, as if the same device were made with coarser sand.
namespace {

void scale_fields(Scene& s, double factor) {
  for (auto& f : scene_fields())
    if (f.px) f.set(s, scaled(json::parse(f.get(s).dump()), factor, f.path));
}

bool scales(Scene s, double factor) {
  try {
    scale_fields(s, factor);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

std::string shown_scale(double f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", f);
  return buf;
}

// The scale nearest `factor` at which every scaled key of `s` stays in its
// range, rounded outward to 3 significant digits; NaN if none up to 1.
double nearest_working_scale(const Scene& s, double factor) {
  if (factor >= 1 || !scales(s, 1)) return NAN;
  double lo = factor, hi = 1;  // lo fails, hi works: a key's minimum is passed going down
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (scales(s, mid) ? hi : lo) = mid;
  }
  const double step = std::pow(10.0, std::floor(std::log10(hi)) - 2);
  double up = std::ceil(hi / step - 1e-9) * step;
  while (!scales(s, up)) up += step;
  return up;
}

}  // namespace

void apply_scale(Scene& s, double factor) {
  if (!(factor > 0) || !std::isfinite(factor) || factor > 8)
    throw InputError("--scale must be in (0, 8], got " + shown_scale(factor));
  const Scene unscaled = s;
  try {
    scale_fields(s, factor);
  } catch (const InputError& e) {
    // The key is one the user may never have set: say what works.
    const double works = nearest_working_scale(unscaled, factor);
    throw InputError("--scale " + shown_scale(factor) + " makes " + e.what() +
                     (std::isnan(works) ? std::string() : "; the smallest --scale that works for this scene is " + shown_scale(works)));
  }
  for (size_t i = 0; i < s.regions.size(); ++i) {  // areas: their place and their own lengths in px
    Area& a = s.regions[i];
    for (double& v : a.rect) v *= factor;
    for (auto& p : a.polygon) p[0] *= factor, p[1] *= factor;
    for (auto& [path, text] : a.settings)
      if (find_field(path)->px) text = scaled(json::parse(text), factor, path).dump();
  }
  s.units.mm_per_pixel /= factor;
  for (auto& d : s.grains.diameter_mm) d /= factor;
}

ordered_json to_json(const Scene& s) {
  ordered_json out = ordered_json::object();
  for (auto& f : scene_fields()) {
    ordered_json* node = &out;
    std::string rest = f.path;
    for (size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1))
      node = &(*node)[rest.substr(0, dot)];
    (*node)[rest] = f.get(s);
  }
  return out;
}

std::string scene_digest(const Scene& s) {
  // Every key the mode reads (the registry says which), not the description.
  ordered_json j = to_json(s);
  j.erase("description");
  for (const Field& f : scene_fields())
    if (!read_in_mode(f, s.mode)) erase_path(j, f.path);
  const std::string text = j.dump();
  uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bit
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
  return buf;
}

bool read_in_mode(const Field& f, Mode m) {
  const unsigned mode = m == Mode::Dem ? kDem : m == Mode::Lammps ? kLammps : kLattice;
  return (f.readers & (kPipeline | kRender | mode)) != 0;
}

bool read_in_mode(const std::string& path, Mode m) {
  const Field* f = find_field(path);
  return f && read_in_mode(*f, m);
}

std::vector<std::string> unread_keys(const Scene& s, const std::vector<std::string>& set_keys) {
  std::vector<std::string> out;
  const Scene defaults;
  for (const Field& f : scene_fields()) {
    if (read_in_mode(f, s.mode)) continue;
    const bool given = std::find(set_keys.begin(), set_keys.end(), f.path) != set_keys.end();
    if (given || f.get(s) != f.get(defaults)) out.push_back(f.path);
  }
  return out;
}

Scene with_calibration(const Scene& s) {
  if (s.lattice.calibration.empty()) return s;
  const std::string path = s.resolve(s.lattice.calibration);
  const std::optional<std::string> text = read_text(path);
  if (!text) throw key_error("lattice.calibration", "cannot read '" + path + "'");
  json doc = parse_nested(*text, false, "scene key 'lattice.calibration': '" + path + "'");
  if (doc.is_discarded() || !doc.is_object() || !doc.contains("lattice") || !doc["lattice"].is_object())
    throw key_error("lattice.calibration", "'" + path + "' is not a calibration (JSON with a \"lattice\" object)");
  json part = json::object();
  part["lattice"] = doc["lattice"];
  part["lattice"].erase("calibration");
  Scene out = s;
  try {
    apply_json(out, part);
  } catch (const InputError& e) {
    throw InputError("calibration '" + path + "': " + e.what());
  }
  return out;
}

void validate(const Scene& s) {
  auto need = [](bool ok, const char* key, const std::string& what) {
    if (!ok) throw key_error(key, what);
  };
  need(s.region.height <= s.window.height, "region.height", "must not exceed window.height");
  need(s.init.row_height_min <= s.init.row_height_max, "init.row_height_min", "must not exceed init.row_height_max");
  need(s.init.cell_width_min <= s.init.cell_width_max, "init.cell_width_min", "must not exceed init.cell_width_max");
  need(s.segment.semi_major_min <= s.segment.semi_major_max, "segment.semi_major_min",
       "must not exceed segment.semi_major_max");
  need(s.segment.eccentricity_min <= s.segment.eccentricity_max, "segment.eccentricity_min",
       "must not exceed segment.eccentricity_max");
  need(s.segment.method != SegmentMethod::Ellipses ||
           s.segment.semi_major_min * std::sqrt(1 - s.segment.eccentricity_max * s.segment.eccentricity_max) >= 0.5,
       "segment.semi_major_min",
       "with segment.eccentricity_max, the smallest ellipses would be under 0.5 px high (more units than grains)");
  double share = 0;
  for (double p : s.grains.proportions) share += p;
  need(share > 0, "grains.proportions", "at least one class needs a share above 0");
  need(s.init.method != InitMethod::Halftone || !s.init.image.empty(), "init.image",
       "init.method=halftone needs an input picture");
  need(s.segment.method != SegmentMethod::Explicit || !s.segment.ellipses.empty(), "segment.ellipses",
       "segment.method=explicit needs at least one ellipse");
  if (s.segment.method == SegmentMethod::Sketch) {
    const auto& k = s.segment.sketch;
    const bool lines = !k.ridges.empty() || !k.arcs.empty();
    need(!(lines && !k.image.empty()), "segment.sketch.image",
         "give the sketch as lines (segment.sketch.ridges and arcs) or as an image, not both");
    need(lines || !k.image.empty(), "segment.sketch.ridges",
         "segment.method=sketch needs ridge lines and arcs (or segment.sketch.image)");
    need(!k.image.empty() || !k.ridges.empty(), "segment.sketch.ridges", "the sketch has no ridge line");
    need(!k.image.empty() || !k.arcs.empty(), "segment.sketch.arcs", "the sketch has no arc-like curve");
    need(k.ridge_color != k.arc_color, "segment.sketch.arc_color", "must differ from segment.sketch.ridge_color");
  }
  if (s.segment.method == SegmentMethod::Pattern) {
    const auto& p = s.segment.pattern;
    need(p.row_height_min <= p.row_height_max, "segment.pattern.row_height_min",
         "must not exceed segment.pattern.row_height_max");
    need(p.semi_major_min <= p.semi_major_max, "segment.pattern.semi_major_min",
         "must not exceed segment.pattern.semi_major_max");
    need(p.minor_share_min <= p.minor_share_max, "segment.pattern.minor_share_min",
         "must not exceed segment.pattern.minor_share_max");
    need(p.row_height_min * p.minor_share_min >= 1, "segment.pattern.row_height_min",
         "with segment.pattern.minor_share_min, ellipses would be under 1 px high");
  }
  for (size_t i = 0; i < s.regions.size(); ++i) {
    const Scene a = area_scene(s, i);
    try {
      validate(a);
    } catch (const InputError& e) {
      throw InputError(with_path_prefix(e, "regions[" + std::to_string(i) + "]"));
    }
  }
  // The sand must fit in the window: at worst every grain is of the largest class.
  double largest = 0;
  for (int k = 0; k < kClasses; ++k) largest = std::max(largest, grain_area_px(s, k));
  double worst = largest * double(s.window.width) * s.region.height;
  double room = double(s.window.width) * s.window.height;
  need(worst <= 0.98 * room, "region.height",
       "the region's sand (up to " + whole(worst) + " px² packed) would not fit in the window (" + whole(room) +
           " px²); lower region.height or grains.diameter_mm");
}

}  // namespace sandpic
