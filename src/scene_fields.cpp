// Every scene key: its path, type, range and help, next to the Scene field it
// sets (defaults live in scene.h). Keys are listed in the order a scene file
// is read by a person: geometry, grains, the pipeline's stages, then output.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "src/errors.h"
#include "src/presets.h"
#include "src/scene_file.h"

namespace sandpic {

namespace {

// A number, or each number of a class's, mapped by `op` into the key's range.
template <class Op>
ordered_json each_number(const Field& f, const ordered_json& value, Op op) {
  auto one = [&](const ordered_json& v) -> ordered_json {
    double d = op(v.get<double>());
    if (f.lo < f.hi) d = std::clamp(d, f.lo, f.hi);
    return f.kind == "integer" ? ordered_json(int64_t(std::floor(d))) : ordered_json(d);
  };
  if (value.is_number()) return one(value);
  if (!value.is_array()) return nullptr;
  ordered_json out = ordered_json::array();
  for (const auto& v : value) out.push_back(one(v));
  return out;
}

}  // namespace

SweepPoint times(double factor) {
  return {"", [factor](const Field& f, const ordered_json& v, const Scene&) {
            return each_number(f, v, [factor](double d) { return d * factor; });
          }};
}
SweepPoint plus(double d) {
  return {"", [d](const Field& f, const ordered_json& v, const Scene&) {
            return each_number(f, v, [d](double x) { return x + d; });
          }};
}
SweepPoint to(ordered_json v, std::string name) {
  return {std::move(name), [v](const Field&, const ordered_json&, const Scene&) { return v; }};
}

std::string sweep_setting(const Field& f, const SweepPoint& p, const ordered_json& changed) {
  if (!p.name.empty()) return f.path + p.name;
  std::string shown = changed.is_string() ? changed.get<std::string>() : "";
  for (const auto& x : changed.is_array() ? changed : ordered_json::array({changed}))
    if (x.is_number()) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", x.get<double>());
      shown += (shown.empty() ? "" : ",") + std::string(buf);
    }
  return f.path + "=" + shown;
}

namespace {

// A value as JSON text for an error message, whatever bytes it holds.
std::string shown(const json& v) { return v.dump(-1, ' ', false, json::error_handler_t::replace); }

std::string num(double d) {
  std::ostringstream o;
  o.precision(10);
  o << d;
  return o.str();
}

double as_number(const json& v, const std::string& path) {
  if (!v.is_number()) throw key_error(path, std::string("expected a number, got ") + v.type_name());
  double d = v.get<double>();
  if (!std::isfinite(d)) throw key_error(path, "must be a finite number");
  return d;
}

double in_range(const json& v, const std::string& path, double lo, double hi) {
  double d = as_number(v, path);
  if (d < lo || d > hi)
    throw key_error(path, "must be in [" + num(lo) + ", " + num(hi) + "], got " + num(d));
  return d;
}

long long as_integer(const json& v, const std::string& path, double lo, double hi) {
  double d = in_range(v, path, lo, hi);
  if (d != std::floor(d)) throw key_error(path, "must be a whole number, got " + num(d));
  return static_cast<long long>(d);
}

Field kind_of(std::string kind, Field f) {
  f.kind = std::move(kind);
  return f;
}

template <class Acc>
Field real(std::string path, Acc acc, double lo, double hi, std::string help, bool px = false) {
  Field f{path, help, px, [acc](const Scene& s) { return ordered_json(acc(s)); },
          [acc, path, lo, hi](Scene& s, const json& v) { acc(s) = in_range(v, path, lo, hi); }};
  f.kind = "number", f.lo = lo, f.hi = hi;
  return f;
}

template <class Acc>
Field integer(std::string path, Acc acc, double lo, double hi, std::string help, bool px = false) {
  Field f{path, help, px, [acc](const Scene& s) { return ordered_json(acc(s)); },
          [acc, path, lo, hi](Scene& s, const json& v) {
            acc(s) = static_cast<std::remove_reference_t<decltype(acc(s))>>(as_integer(v, path, lo, hi));
          }};
  f.kind = "integer", f.lo = lo, f.hi = hi;
  return f;
}

constexpr double kMaxSeed = 9007199254740991.0;  // 2^53 - 1: exact in every JSON reader

uint64_t as_seed(const json& v, const std::string& path) {
  return static_cast<uint64_t>(as_integer(v, path, 0, kMaxSeed));
}

template <class Acc>
Field optional_seed(std::string path, Acc acc, std::string help) {
  Field f{path, help, false,
          [acc](const Scene& s) {
            const auto& o = acc(s);
            return o ? ordered_json(*o) : ordered_json(nullptr);
          },
          [acc, path](Scene& s, const json& v) {
            if (v.is_null()) acc(s).reset();
            else acc(s) = as_seed(v, path);
          }};
  f.kind = "seed", f.lo = 0, f.hi = kMaxSeed;
  return f;
}

template <class E, class Acc>
Field choice(std::string path, Acc acc, std::vector<std::pair<std::string, E>> names, std::string help) {
  std::string list;
  for (auto& [n, e] : names) list += (list.empty() ? "" : " | ") + n;
  Field f{path, help + " (" + list + ")", false,
          [acc, names](const Scene& s) {
            for (auto& [n, e] : names)
              if (e == acc(s)) return ordered_json(n);
            return ordered_json(nullptr);
          },
          [acc, names, path, list](Scene& s, const json& v) {
            if (v.is_string())
              for (auto& [n, e] : names)
                if (n == v.get<std::string>()) {
                  acc(s) = e;
                  return;
                }
            throw key_error(path, "must be one of " + list + ", got " + shown(v));
          }};
  f.kind = "choice";
  for (auto& [n, e] : names) f.choices.push_back(n);
  return f;
}

template <class Acc>
Field text(std::string path, Acc acc, std::string help) {
  Field f{path, help, false, [acc](const Scene& s) { return ordered_json(acc(s)); },
          [acc, path](Scene& s, const json& v) {
            if (!v.is_string()) throw key_error(path, std::string("expected a string, got ") + v.type_name());
            acc(s) = v.get<std::string>();
          }};
  f.kind = "text";
  return f;
}

const json& element(const json& v, const std::string& path, size_t n) {
  if (!v.is_array() || v.size() != n)
    throw key_error(path, "expected an array of " + std::to_string(n) + " values, got " + shown(v));
  return v;
}

std::array<double, kClasses> reals4(const json& v, const std::string& path, double lo, double hi) {
  element(v, path, kClasses);
  std::array<double, kClasses> out{};
  for (int k = 0; k < kClasses; ++k) out[k] = in_range(v[k], path + "[" + std::to_string(k) + "]", lo, hi);
  return out;
}

template <class Acc>
Field per_class(std::string path, Acc acc, double lo, double hi, std::string help, bool px = false) {
  Field f{path, help + ", per class S1..S4", px, [acc](const Scene& s) { return ordered_json(acc(s)); },
          [acc, path, lo, hi](Scene& s, const json& v) { acc(s) = reals4(v, path, lo, hi); }};
  f.kind = "per_class", f.lo = lo, f.hi = hi;
  return f;
}

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

// A colour is "#rrggbb" or [r, g, b] with components 0..255.
Rgb as_rgb(const json& v, const std::string& path) {
  if (v.is_string()) {
    std::string t = v.get<std::string>();
    bool hex6 = t.size() == 7 && t[0] == '#' &&
                std::all_of(t.begin() + 1, t.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
    if (hex6) {
      unsigned long v = std::stoul(t.substr(1), nullptr, 16);
      return Rgb{uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
    }
    throw key_error(path, "a colour is \"#rrggbb\" or [r, g, b], got " + shown(v));
  }
  element(v, path, 3);
  return Rgb{uint8_t(as_integer(v[0], path + "[0]", 0, 255)), uint8_t(as_integer(v[1], path + "[1]", 0, 255)),
             uint8_t(as_integer(v[2], path + "[2]", 0, 255))};
}

template <class Acc>
Field colour(std::string path, Acc acc, std::string help) {
  Field f{path, help, false, [acc](const Scene& s) { return ordered_json(hex(acc(s))); },
          [acc, path](Scene& s, const json& v) { acc(s) = as_rgb(v, path); }};
  f.kind = "colour";
  return f;
}

// Objects inside lists (ellipses, cell overrides) are read key by key, with
// the same refusal of unknown keys as the top level.
template <class T>
std::vector<T> list_of(const json& v, const std::string& path,
                       const std::vector<std::pair<std::string, std::function<void(T&, const json&, const std::string&)>>>& keys,
                       const std::vector<std::string>& required) {
  if (!v.is_array()) throw key_error(path, std::string("expected an array, got ") + v.type_name());
  std::vector<T> out;
  for (size_t i = 0; i < v.size(); ++i) {
    std::string p = path + "[" + std::to_string(i) + "]";
    if (!v[i].is_object()) throw key_error(p, "expected an object");
    T item{};
    for (auto& [k, val] : v[i].items()) {
      bool known = false;
      for (auto& [name, set] : keys)
        if (name == k) set(item, val, p + "." + k), known = true;
      if (!known) throw key_error(p + "." + k, "unknown key");
    }
    for (auto& r : required)
      if (!v[i].contains(r)) throw key_error(p + "." + r, "missing");
    out.push_back(item);
  }
  return out;
}

// A line: [[x, y], [x, y], ...], at least two points.
Polyline as_polyline(const json& v, const std::string& p) {
  if (!v.is_array() || v.size() < 2) throw key_error(p, "expected a line of at least two [x, y] points, got " + shown(v));
  Polyline line;
  for (size_t j = 0; j < v.size(); ++j) {
    const std::string q = p + "[" + std::to_string(j) + "]";
    element(v[j], q, 2);
    line.push_back({in_range(v[j][0], q + "[0]", -1e6, 1e6), in_range(v[j][1], q + "[1]", -1e6, 1e6)});
  }
  return line;
}

// Lines of a sketch: [[[x, y], [x, y], ...], ...].
template <class Acc>
Field polylines(std::string path, Acc acc, std::string help) {
  Field f{path, help, true,
          [acc](const Scene& s) {
            ordered_json out = ordered_json::array();
            for (const Polyline& line : acc(s)) {
              ordered_json pts = ordered_json::array();
              for (const auto& p : line) pts.push_back({p[0], p[1]});
              out.push_back(pts);
            }
            return out;
          },
          [acc, path](Scene& s, const json& v) {
            if (!v.is_array()) throw key_error(path, std::string("expected an array of lines, got ") + v.type_name());
            std::vector<Polyline> lines;
            for (size_t i = 0; i < v.size(); ++i) lines.push_back(as_polyline(v[i], path + "[" + std::to_string(i) + "]"));
            acc(s) = std::move(lines);
          }};
  f.kind = "list";
  return f;
}

template <class Acc>
Field boolean(std::string path, Acc acc, std::string help) {
  Field f{path, help, false, [acc](const Scene& s) { return ordered_json(acc(s)); },
          [acc, path](Scene& s, const json& v) {
            if (!v.is_boolean()) throw key_error(path, std::string("expected true or false, got ") + shown(v));
            acc(s) = v.get<bool>();
          }};
  f.kind = "boolean";
  return f;
}

Field ellipses_field() {
  using Setter = std::function<void(EllipseSpec&, const json&, const std::string&)>;
  std::vector<std::pair<std::string, Setter>> keys = {
      {"cx", [](EllipseSpec& e, const json& v, const std::string& p) { e.cx = in_range(v, p, -1e6, 1e6); }},
      {"cy", [](EllipseSpec& e, const json& v, const std::string& p) { e.cy = in_range(v, p, -1e6, 1e6); }},
      {"a", [](EllipseSpec& e, const json& v, const std::string& p) { e.a = in_range(v, p, 0.5, 1e6); }},
      {"b", [](EllipseSpec& e, const json& v, const std::string& p) { e.b = in_range(v, p, 0.5, 1e6); }},
      {"angle_deg",
       [](EllipseSpec& e, const json& v, const std::string& p) { e.angle_deg = in_range(v, p, -360, 360); }},
  };
  return kind_of("list", Field{"segment.ellipses",
          "explicit ellipses for segment.method=explicit: [{cx, cy, a, b, angle_deg}] in window px (y down)", true,
          [](const Scene& s) {
            ordered_json out = ordered_json::array();
            for (auto& e : s.segment.ellipses)
              out.push_back({{"cx", e.cx}, {"cy", e.cy}, {"a", e.a}, {"b", e.b}, {"angle_deg", e.angle_deg}});
            return out;
          },
          [keys](Scene& s, const json& v) {
            s.segment.ellipses = list_of<EllipseSpec>(v, "segment.ellipses", keys, {"cx", "cy", "a", "b"});
          }});
}

// paper §10, Fig. 16: figures over the sand.
Field figures_field() {
  using Setter = std::function<void(Figure&, const json&, const std::string&)>;
  std::vector<std::pair<std::string, Setter>> keys = {
      {"mask",
       [](Figure& f, const json& v, const std::string& p) {
         if (!v.is_string()) throw key_error(p, std::string("expected a string, got ") + v.type_name());
         f.mask = v.get<std::string>();
       }},
      {"polygon", [](Figure& f, const json& v, const std::string& p) { f.polygon = as_polyline(v, p); }},
      {"x", [](Figure& f, const json& v, const std::string& p) { f.x = in_range(v, p, -1e6, 1e6); }},
      {"y", [](Figure& f, const json& v, const std::string& p) { f.y = in_range(v, p, -1e6, 1e6); }},
      {"scale", [](Figure& f, const json& v, const std::string& p) { f.scale = in_range(v, p, 1e-3, 1e3); }},
  };
  return kind_of("list", Field{"render.figures",
          "figures over the sand (§10, Fig. 16): [{mask: image, x, y, scale} or {polygon: [[x, y], ...]}]; "
          "sand on a figure is drawn in C1 (0.7) and C2 (0.3)",
          true,
          [](const Scene& s) {
            ordered_json out = ordered_json::array();
            for (const Figure& f : s.render.figures) {
              ordered_json o;
              if (!f.mask.empty()) o = {{"mask", f.mask}, {"x", f.x}, {"y", f.y}, {"scale", f.scale}};
              ordered_json pts = ordered_json::array();
              for (const auto& p : f.polygon) pts.push_back({p[0], p[1]});
              if (!f.polygon.empty()) o["polygon"] = pts;
              out.push_back(o);
            }
            return out;
          },
          [keys](Scene& s, const json& v) {
            s.render.figures = list_of<Figure>(v, "render.figures", keys, {});
            for (size_t i = 0; i < s.render.figures.size(); ++i)
              if (s.render.figures[i].mask.empty() == s.render.figures[i].polygon.empty())
                throw key_error("render.figures[" + std::to_string(i) + "]", "needs a mask image or a polygon (one of them)");
          }});
}

Field overrides_field() {
  using Setter = std::function<void(CellOverride&, const json&, const std::string&)>;
  std::vector<std::pair<std::string, Setter>> keys = {
      {"cell", [](CellOverride& c, const json& v, const std::string& p) { c.cell = int(as_integer(v, p, 0, 1e7)); }},
      {"dominant",
       [](CellOverride& c, const json& v, const std::string& p) { c.dominant = int(as_integer(v, p, 1, 4)) - 1; }},
      {"secondary",
       [](CellOverride& c, const json& v, const std::string& p) { c.secondary = int(as_integer(v, p, 1, 4)) - 1; }},
  };
  return kind_of("list", Field{"init.cell_overrides",
          "per-cell classes chosen by hand (paper §3): [{cell, dominant, secondary}], cells numbered row by row "
          "from the top-left, classes 1..4",
          false,
          [](const Scene& s) {
            ordered_json out = ordered_json::array();
            for (auto& c : s.init.cell_overrides)
              out.push_back({{"cell", c.cell}, {"dominant", c.dominant + 1}, {"secondary", c.secondary + 1}});
            return out;
          },
          [keys](Scene& s, const json& v) {
            s.init.cell_overrides =
                list_of<CellOverride>(v, "init.cell_overrides", keys, {"cell", "dominant", "secondary"});
          }});
}

Field colours_field() {
  return kind_of("colours", Field{"grains.colors", "C1..C4, one per class: \"#rrggbb\" or [r, g, b]", false,
          [](const Scene& s) {
            ordered_json out = ordered_json::array();
            for (auto c : s.grains.colors) out.push_back(hex(c));
            return out;
          },
          [](Scene& s, const json& v) {
            element(v, "grains.colors", kClasses);
            for (int k = 0; k < kClasses; ++k)
              s.grains.colors[k] = as_rgb(v[k], "grains.colors[" + std::to_string(k) + "]");
          }});
}

Field repose_deg_field() {
  Field f{"lattice.repose_deg",
          "angle of repose in degrees per class S1..S4, overriding repose_gain·friction; null: from friction", false,
          [](const Scene& s) {
            return s.lattice.repose_deg ? ordered_json(*s.lattice.repose_deg) : ordered_json(nullptr);
          },
          [](Scene& s, const json& v) {
            if (v.is_null()) s.lattice.repose_deg.reset();
            else s.lattice.repose_deg = reals4(v, "lattice.repose_deg", 1, 75);
          }};
  f.kind = "per_class", f.lo = 1, f.hi = 75;
  // ±5° around the angles the lattice uses (from friction when not set).
  for (double d : {-5.0, 5.0})
    f.sweep.push_back({d > 0 ? "+5" : "-5", [d](const Field&, const ordered_json&, const Scene& s) {
                         ordered_json a = ordered_json::array();
                         for (int k = 0; k < kClasses; ++k) a.push_back(std::clamp(repose_angle_deg(s, k) + d, 1.0, 75.0));
                         return a;
                       }});
  return f;
}

// The picture alone: the smaller grains drawn 1.5x their share where they
// mix with bigger ones, or every share back at 1 when they differ.
SweepPoint other_picture_shares() {
  return {"", [](const Field&, const ordered_json&, const Scene& s) {
            std::array<double, kClasses> share = s.lattice.picture_share;
            const auto& d = s.grains.diameter_mm;
            if (std::all_of(share.begin(), share.end(), [&](double v) { return v == share[0]; })) {
              for (int k = 0; k < kClasses; ++k)
                if (d[size_t(k)] < *std::max_element(d.begin(), d.end())) share[size_t(k)] *= 1.5;
            } else {
              share.fill(1);
            }
            return ordered_json(share);
          }};
}

// Points that only a settling arrival has: what landing in falling order
// would cost, and busy landing spots off, or on at the value the DEM's
// outlets took at 20,000 grains.
SweepPoint when_settling(std::function<ordered_json(const ordered_json&)> change) {
  return {"", [change](const Field&, const ordered_json& v, const Scene& s) {
            return s.lattice.arrival == LatticeArrival::Settling ? change(v) : ordered_json(nullptr);
          }};
}

Field seed_field() {
  Field f{"seed", "sets the layout and the physics seed at once", false,
          [](const Scene& s) { return ordered_json(s.seed); },
          [](Scene& s, const json& v) { s.seed = as_seed(v, "seed"); }};
  f.kind = "seed", f.lo = 0, f.hi = kMaxSeed;
  return f;
}

// paper §9: a preset's keys, read when the key is (a scene file reads its
// "preset" before its other keys, so they override it).
Field preset_field() {
  std::string names;
  for (const Preset& p : presets()) names += (names.empty() ? "" : " | ") + p.name;
  Field f{"preset", "a base from §9's rules, read first; the scene's own keys override it (" + names + ")", false,
          [](const Scene& s) { return ordered_json(s.preset); },
          [names](Scene& s, const json& v) {
            if (!v.is_string()) throw key_error("preset", std::string("expected a string, got ") + v.type_name());
            const std::string name = v.get<std::string>();
            if (name.empty()) return void(s.preset.clear());
            const Preset* p = find_preset(name);
            if (!p) throw key_error("preset", "unknown preset " + shown(v) + " (" + names + ")");
            apply_json(s, json::parse(p->json));
            s.preset = name;
          }};
  f.kind = "choice";
  f.choices.push_back("");  // none
  for (const Preset& p : presets()) f.choices.push_back(p.name);
  return f;
}

// An area's own keys, flattened to (path, JSON text); every value checked
// against its field here, so errors name regions[i].path.
void flatten_area(const json& v, const std::string& path, const std::string& where,
                  std::vector<std::pair<std::string, std::string>>& out) {
  const auto& fields = scene_fields();
  const Field* field = find_field(path);
  const bool leaf = field != nullptr;
  const bool prefix = std::any_of(fields.begin(), fields.end(),
                                  [&](const Field& f) { return f.path.rfind(path + ".", 0) == 0; });
  if (!leaf && prefix && v.is_object()) {
    for (auto& [k, child] : v.items()) flatten_area(child, path.empty() ? k : path + "." + k, where, out);
    return;
  }
  if (!leaf) throw InputError("scene key '" + where + "." + path + "': unknown key (did you mean '" + nearest_key(path) + "'?)");
  if (!field->area)
    throw InputError("scene key '" + where + "." + path + "': an area sets only init.*, segment.* and grains.proportions");
  out.emplace_back(path, v.dump());
}

Area as_area(const json& v, const std::string& where) {
  if (!v.is_object()) throw key_error(where, "expected an object");
  Area a;
  for (auto& [k, val] : v.items()) {
    const std::string p = where + "." + k;
    if (k == "rect") {
      element(val, p, 4);
      for (int i = 0; i < 4; ++i) a.rect[i] = in_range(val[i], p + "[" + std::to_string(i) + "]", -1e6, 1e6);
      if (a.rect[2] <= a.rect[0] || a.rect[3] <= a.rect[1]) throw key_error(p, "needs x0 < x1 and y0 < y1");
    } else if (k == "polygon") {
      a.polygon = as_polyline(val, p);
      if (a.polygon.size() < 3) throw key_error(p, "a polygon needs at least three points");
    } else if (k == "preset") {
      if (!val.is_string() || !find_preset(val.get<std::string>()))
        throw key_error(p, "unknown preset " + shown(val) + " (`sandpic scene --presets` lists them)");
      a.preset = val.get<std::string>();
    } else {
      flatten_area(val, k, where, a.settings);
    }
  }
  // Every value checked once, with the path it has in the file.
  Scene probe;
  for (auto& [path, text] : a.settings) {
    try {
      apply_setting(probe, path + "=" + text);
    } catch (const InputError& e) {
      throw InputError(with_path_prefix(e, where));
    }
  }
  return a;
}

ordered_json area_json(const Area& a) {
  ordered_json o;
  o["rect"] = a.rect;
  if (!a.polygon.empty()) {
    ordered_json pts = ordered_json::array();
    for (const auto& p : a.polygon) pts.push_back({p[0], p[1]});
    o["polygon"] = pts;
  }
  if (!a.preset.empty()) o["preset"] = a.preset;
  for (auto& [path, text] : a.settings) {
    ordered_json* node = &o;
    std::string rest = path;
    for (size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1))
      node = &(*node)[rest.substr(0, dot)];
    (*node)[rest] = ordered_json::parse(text);
  }
  return o;
}

// paper §10, Fig. 17: areas of the region with their own settings.
Field regions_field() {
  return kind_of("list", Field{"regions",
          "areas of the region with their own tessellation, colour mix and segmentation (§10, Fig. 17): "
          "[{rect: [x0, y0, x1, y1] or polygon: [[x, y], ...], preset, init: {...}, segment: {...}, "
          "grains: {proportions}}]; a pixel belongs to the first area listed that holds it",
          false,
          [](const Scene& s) {
            ordered_json out = ordered_json::array();
            for (const Area& a : s.regions) out.push_back(area_json(a));
            return out;
          },
          [](Scene& s, const json& v) {
            if (!v.is_array()) throw key_error("regions", std::string("expected an array, got ") + v.type_name());
            std::vector<Area> areas;
            for (size_t i = 0; i < v.size(); ++i) areas.push_back(as_area(v[i], "regions[" + std::to_string(i) + "]"));
            s.regions = std::move(areas);
          }});
}

// The table, in the order a person reads a scene file, section by section:
// which stages read a section's keys, and whether an area may set them.
std::vector<Field> make_fields() {
  std::vector<Field> all;
  auto section = [&all](unsigned readers, bool area, std::vector<Field> keys) {
    for (Field& f : keys) {
      if (!f.readers) f.readers = readers;  // not declared otherwise in the entry
      f.area = f.area || area;
      all.push_back(std::move(f));
    }
  };
  section(kPipeline, false, {
      text("description", [](auto& s) -> auto& { return s.description; }, "free text about the scene, for people"),
      preset_field(),
      integer("window.width", [](auto& s) -> auto& { return s.window.width; }, 8, 20000, "window width, px (§4.1)", true),
      integer("window.height", [](auto& s) -> auto& { return s.window.height; }, 8, 20000, "window height, px", true),
      integer("region.height", [](auto& s) -> auto& { return s.region.height; }, 1, 20000,
              "initialization region height at the top of the window, px (§4.1)", true),
      real("units.mm_per_pixel", [](auto& s) -> auto& { return s.units.mm_per_pixel; }, 1e-4, 100,
           "mm per pixel; one grain per pixel of the region"),
      real("units.packing", [](auto& s) -> auto& { return s.units.packing; }, 0.3, 0.91,
           "2D packing fraction of a pile"),
      per_class("grains.density_g_cm3", [](auto& s) -> auto& { return s.grains.density_g_cm3; }, 0.01, 100,
                "density, g/cm³ (§4.1)"),
      per_class("grains.diameter_mm", [](auto& s) -> auto& { return s.grains.diameter_mm; }, 1e-4, 100,
                "diameter, mm (§4.1)"),
      per_class("grains.proportions", [](auto& s) -> auto& { return s.grains.proportions; }, 0, 1,
                "share of cells whose dominant class it is (§4.4, Algorithm 1)")
          .in_area(),
      // Only the picture's colours: no stage before it reads them (a colour
      // change in the studio keeps the layout).
      colours_field().read_by(kRender),
  });
  // paper §4-5: what an area of the region (Fig. 17) may make its own.
  section(kPipeline, true, {
      choice<InitMethod>("init.method", [](auto& s) -> auto& { return s.init.method; },
                         {{"tessellation", InitMethod::Tessellation}, {"halftone", InitMethod::Halftone}},
                         "how the region is filled (§4)"),
      text("init.image", [](auto& s) -> auto& { return s.init.image; },
           "input picture for init.method=halftone, resized to the region if its size differs (§4.2)"),
      choice<TessellationKind>("init.tessellation", [](auto& s) -> auto& { return s.init.tessellation; },
                               {{"uniform", TessellationKind::Uniform},
                                {"varying", TessellationKind::Varying},
                                {"strips", TessellationKind::Strips}},
                               "cell layout (§4.3: Fig. 4, Fig. 5; §9 strips)"),
      real("init.cell_width", [](auto& s) -> auto& { return s.init.cell_width; }, 1, 1e5,
           "uniform cell width, px", true),
      real("init.cell_height", [](auto& s) -> auto& { return s.init.cell_height; }, 1, 1e5,
           "uniform cell height, px", true),
      real("init.row_height_min", [](auto& s) -> auto& { return s.init.row_height_min; }, 1, 1e5,
           "varying: row height at the top; strips: smallest strip, px", true),
      real("init.row_height_max", [](auto& s) -> auto& { return s.init.row_height_max; }, 1, 1e5,
           "varying: row height at the bottom; strips: largest strip, px", true),
      real("init.cell_width_min", [](auto& s) -> auto& { return s.init.cell_width_min; }, 1, 1e5,
           "varying: narrowest cell, px", true),
      real("init.cell_width_max", [](auto& s) -> auto& { return s.init.cell_width_max; }, 1, 1e5,
           "varying: widest cell, px", true),
      real("init.dominant_share", [](auto& s) -> auto& { return s.init.dominant_share; }, 0, 1,
           "probability that a grain takes its cell's dominant class (§4.4: 0.8)"),
      overrides_field(),
      choice<SegmentMethod>("segment.method", [](auto& s) -> auto& { return s.segment.method; },
                            {{"ellipses", SegmentMethod::Ellipses},
                             {"explicit", SegmentMethod::Explicit},
                             {"cells", SegmentMethod::Cells},
                             {"sketch", SegmentMethod::Sketch},
                             {"pattern", SegmentMethod::Pattern}},
                            "falling units: automatic ellipses (§5.1), listed ellipses, the cells (Fig. 4b, 5b), "
                            "ellipses under a sketch's crossings (§5.2), or a regular pattern's rows (§10, Fig. 18)"),
      real("segment.semi_major_min", [](auto& s) -> auto& { return s.segment.semi_major_min; }, 1, 1e5,
           "semi-major axis of the top row of ellipses, px", true),
      real("segment.semi_major_max", [](auto& s) -> auto& { return s.segment.semi_major_max; }, 1, 1e5,
           "semi-major axis of the bottom row of ellipses, px", true),
      real("segment.eccentricity_min", [](auto& s) -> auto& { return s.segment.eccentricity_min; }, 0, 0.999,
           "smallest ellipse eccentricity (§9: small = steep piles)"),
      real("segment.eccentricity_max", [](auto& s) -> auto& { return s.segment.eccentricity_max; }, 0, 0.999,
           "largest ellipse eccentricity"),
      ellipses_field(),
      polylines("segment.sketch.ridges", [](auto& s) -> auto& { return s.segment.sketch.ridges; },
                "sketch (§5.2): ridge lines, each [[x, y], ...] in window px (y down)"),
      polylines("segment.sketch.arcs", [](auto& s) -> auto& { return s.segment.sketch.arcs; },
                "sketch (§5.2): arc-like curves across the ridge lines, each [[x, y], ...] in window px"),
      text("segment.sketch.image", [](auto& s) -> auto& { return s.segment.sketch.image; },
           "sketch as a picture of the region instead: ridge and arc strokes in the two colours below"),
      colour("segment.sketch.ridge_color", [](auto& s) -> auto& { return s.segment.sketch.ridge_color; },
             "stroke colour of the ridge lines in segment.sketch.image"),
      colour("segment.sketch.arc_color", [](auto& s) -> auto& { return s.segment.sketch.arc_color; },
             "stroke colour of the arc-like curves in segment.sketch.image"),
      real("segment.sketch.shrink_per_px", [](auto& s) -> auto& { return s.segment.sketch.shrink_per_px; }, 0, 10,
           "§5.2's α: semi-major axis a_i = 0.5 A_m - α P_i(y), P_i(y) the crossing's height above the region's bottom"),
      real("segment.sketch.semi_major_floor", [](auto& s) -> auto& { return s.segment.sketch.semi_major_floor; }, 1, 1e5,
           "smallest semi-major axis of a sketch ellipse, px (high crossings)", true),
      real("segment.sketch.bottom_band", [](auto& s) -> auto& { return s.segment.sketch.bottom_band; }, 0.01, 1,
           "A_m = region width / ridge lines reaching this share of the region above its bottom"),
      boolean("segment.sketch.narrow", [](auto& s) -> auto& { return s.segment.sketch.narrow; },
              "§5.2, Fig. 7c: insert two long narrow ellipses on top of an ellipse whose next crossing up its ridge is far"),
      real("segment.sketch.narrow_spacing", [](auto& s) -> auto& { return s.segment.sketch.narrow_spacing; }, 0, 100,
           "§5.2: far means farther than this times the lower ellipse's semi-minor axis"),
      real("segment.pattern.row_height_min", [](auto& s) -> auto& { return s.segment.pattern.row_height_min; }, 1, 1e5,
           "pattern (Fig. 18): lowest row of ellipse units, px", true),
      real("segment.pattern.row_height_max", [](auto& s) -> auto& { return s.segment.pattern.row_height_max; }, 1, 1e5,
           "pattern: highest row, px", true),
      real("segment.pattern.semi_major_min", [](auto& s) -> auto& { return s.segment.pattern.semi_major_min; }, 1, 1e5,
           "pattern: smallest semi-major axis of a unit's two ellipses, px", true),
      real("segment.pattern.semi_major_max", [](auto& s) -> auto& { return s.segment.pattern.semi_major_max; }, 1, 1e5,
           "pattern: largest semi-major axis, px", true),
      real("segment.pattern.minor_share_min", [](auto& s) -> auto& { return s.segment.pattern.minor_share_min; }, 0.05, 1,
           "pattern: smallest semi-minor axis, as a share of half the row height"),
      real("segment.pattern.minor_share_max", [](auto& s) -> auto& { return s.segment.pattern.minor_share_max; }, 0.05, 1,
           "pattern: largest semi-minor axis, as a share of half the row height"),
      real("segment.pattern.separator", [](auto& s) -> auto& { return s.segment.pattern.separator; }, 0, 1e4,
           "pattern: height of the thin rectangles between rows, px (0: none)", true),
      integer("segment.pattern.separator_class", [](auto& s) -> auto& { return s.segment.pattern.separator_class; }, 0, 4,
              "pattern: class S1..S4 of the separators' grains (0: as the tessellation filled them)"),
  });
  section(kPipeline, false, {
      real("order.row_tolerance", [](auto& s) -> auto& { return s.order.row_tolerance; }, 0, 1e5,
           "units whose centres differ by at most this in y form one row (§6), px", true),
      real("release.outlet_width_mm", [](auto& s) -> auto& { return s.release.outlet_width_mm; }, 0, 1e4,
           "outlet at the middle of a unit's lowest edge, mm (§7: 15 mm)"),
      real("release.gravity_m_s2", [](auto& s) -> auto& { return s.release.gravity_m_s2; }, 0.01, 1000,
           "gravity in Eq. 1-2, m/s²"),
      choice<Mode>("mode", [](auto& s) -> auto& { return s.mode; },
                   {{"lattice", Mode::Lattice}, {"dem", Mode::Dem}, {"lammps", Mode::Lammps}},
                   "simulation backend (lammps: LAMMPS's granular DEM run by `lmp`, the reference for dem)"),
      seed_field(),
      optional_seed("layout_seed", [](auto& s) -> auto& { return s.layout_seed; },
                    "tessellation, colours, ellipses, falling-order ties; null: seed"),
      optional_seed("physics_seed", [](auto& s) -> auto& { return s.physics_seed; },
                    "the simulation's own randomness; null: seed"),
  });
  section(kLattice | kDem | kLammps, false, {  // the lattice's angle of repose follows the friction
      real("physics.friction", [](auto& s) -> auto& { return s.physics.friction; }, 0, 10,
           "Coulomb friction, static = dynamic (§7: 0.4)"),
      real("physics.restitution", [](auto& s) -> auto& { return s.physics.restitution; }, 0, 1,
           "restitution (§7: 0.1)")
          .read_by(kDem | kLammps),
  });
  section(kLattice, false, {
      real("lattice.resolution", [](auto& s) -> auto& { return s.lattice.resolution; }, 0.05, 8,
           "height-field columns per pixel")
          .swept({times(0.5), times(2)}),
      per_class("lattice.repose_gain", [](auto& s) -> auto& { return s.lattice.repose_gain; }, 0.01, 20,
                "tan(angle of repose) = gain · physics.friction"),
      repose_deg_field(),
      per_class("lattice.runout_px", [](auto& s) -> auto& { return s.lattice.runout_px; }, 0, 1e4,
                "how far a grain keeps going down a slope once stable, px (grain-scale: --scale keeps it)")
          .swept({to({0, 0, 0, 0}, "=0"), {"*2+2", [](const Field& f, const ordered_json& v, const Scene&) {
                                              return each_number(f, v, [](double r) { return r * 2 + 2; });
                                            }}}),
      real("lattice.bulk", [](auto& s) -> auto& { return s.lattice.bulk; }, 0.25, 4,
           "area a grain takes in the pile, as a multiple of its packed area (DEM piles pack looser)")
          .swept({times(0.95), times(1.05)}),
      real("lattice.surface_px", [](auto& s) -> auto& { return s.lattice.surface_px; }, 0, 100,
           "the DEM's loose top layer: each column's top 10 px of sand drawn this much thicker, px (--scale keeps it)")
          .swept({plus(2)}),
      real("lattice.trap_rate", [](auto& s) -> auto& { return s.lattice.trap_rate; }, 0, 1,
           "chance per column slid that a rolling grain is caught on the flank (paper §8, BCRE [24]); 0: never")
          .fitted({0, 0.2, 1}),
      real("lattice.trap_deg", [](auto& s) -> auto& { return s.lattice.trap_deg; }, 0, 45,
           "how much steeper than its angle of repose a flank may be where a rolling grain is caught, degrees")
          .fitted({3, 5}),
      real("lattice.spot_busy_s", [](auto& s) -> auto& { return s.lattice.spot_busy_s; }, 0, 10,
           "seconds a landing spot (a pixel column) stays busy after a grain lands on it; grains due there wait, "
           "as the DEM's insertion does (settling arrival only); 0: never")
          .fitted({0, 0.006, 0.008, 0.010, 0.012, 0.014})
          .swept({when_settling([](const ordered_json& v) { return ordered_json(v.get<double>() > 0 ? 0 : 0.01); })}),
      per_class("lattice.picture_share", [](auto& s) -> auto& { return s.lattice.picture_share; }, 0.05, 20,
                "where classes mix in a column, each is drawn in proportion to area · share, as the DEM's "
                "nearest-grain picture shows small grains among big ones larger than their area (1: by area)")
          .swept({other_picture_shares()}),
      text("lattice.calibration", [](auto& s) -> auto& { return s.lattice.calibration; },
           "a file written by sandpic calibrate: its lattice values replace the scene's (lattice mode only)"),
      choice<LatticeArrival>("lattice.arrival", [](auto& s) -> auto& { return s.lattice.arrival; },
                      {{"settling", LatticeArrival::Settling}, {"release", LatticeArrival::Release}},
                      "grains land in the order they reach the pile (settling: dem.release_rate, Eq. 1, then the "
                      "class's settling speed in dem.water, as the DEM) or in falling order (release)")
          .swept({when_settling([](const ordered_json&) { return ordered_json("release"); })}),
      integer("lattice.window_columns", [](auto& s) -> auto& { return s.lattice.window_columns; }, 0, 64,
              "columns the non-local slope rule looks ahead; 0: chosen per class"),
  });
  // The DEM's keys; the device's release rate and water are the lattice's too
  // (lattice.arrival settling lands grains as they reach the pile).
  section(kDem, false, {
      choice<Layers>("dem.layers", [](auto& s) -> auto& { return s.dem.layers; },
                     {{"three", Layers::Three}, {"bcre", Layers::Bcre}, {"all-dynamic", Layers::AllDynamic}},
                     "DEM layer model (§8): three layers, two (BCRE: static grains become a height field), or none")
          .swept({to("three"), to("bcre"), to("all-dynamic")}),
      real("dem.step_diameters", [](auto& s) -> auto& { return s.dem.step_diameters; }, 0.005, 1,
           "the time step: the most a grain moves in one step, in small-grain diameters")
          .swept({times(2), times(0.5)}),
      integer("dem.solver_iterations", [](auto& s) -> auto& { return s.dem.solver_iterations; }, 1, 1000,
              "Bullet constraint solver iterations per step")
          .swept({times(0.5), times(2)}),
      real("dem.release_rate", [](auto& s) -> auto& { return s.dem.release_rate; }, 1, 1e9,
           "grains released per simulated second (§7)")
          .read_by(kLattice | kDem | kLammps)
          .swept({times(0.5), times(2)}),
      real("dem.rolling_resistance", [](auto& s) -> auto& { return s.dem.rolling_resistance; }, 0, 10,
           "rolling resistance μ_r: a contact's torque is at most μ_r·R_r·N, R_r = R_a·R_b/(R_a+R_b) (0: round grains spread flat)")
          .read_by(kDem | kLammps),
      boolean("dem.water", [](auto& s) -> auto& { return s.dem.water; },
              "the device's water: drag and buoyancy per class density")
          .read_by(kLattice | kDem | kLammps),
      real("dem.water_density_g_cm3", [](auto& s) -> auto& { return s.dem.water_density_g_cm3; }, 0, 50,
           "water density, g/cm³")
          .read_by(kLattice | kDem | kLammps),
      real("dem.water_viscosity_pa_s", [](auto& s) -> auto& { return s.dem.water_viscosity_pa_s; }, 1e-6, 100,
           "water viscosity, Pa·s")
          .read_by(kLattice | kDem | kLammps),
      integer("dem.cycle_steps", [](auto& s) -> auto& { return s.dem.cycle_steps; }, 1, 100000,
              "steps per simulation cycle: the layers are updated once a cycle (§8.1: 40)"),
      real("dem.rest_displacement", [](auto& s) -> auto& { return s.dem.rest_displacement; }, 0, 10,
           "a grain is at rest when it moved less than this in a cycle, in its diameters"),
      integer("dem.patience_cycles", [](auto& s) -> auto& { return s.dem.patience_cycles; }, 0, 100000,
              "a grain at rest this many cycles in a row becomes static on any slope (0: never; faster, less exact)"),
      real("dem.slope_limit_deg", [](auto& s) -> auto& { return s.dem.slope_limit_deg; }, 0, 90,
           "§8.1's α: a grain becomes static only where its steepest drop to the static layer is below it "
           "(0: the angle the grains' piles stand at when every grain is a body, from friction and rolling "
           "resistance, + dem.slope_margin_deg)"),
      real("dem.slope_margin_deg", [](auto& s) -> auto& { return s.dem.slope_margin_deg; }, 0, 60,
           "with dem.slope_limit_deg 0: α is the all-dynamic heap angle plus this"),
      real("dem.slope_baseline_diameters", [](auto& s) -> auto& { return s.dem.slope_baseline_diameters; }, 0.5, 1000,
           "§8.1's θ is the steepest drop to the static layer this far to either side, in the largest grain's diameters"),
      real("dem.static_thickness_diameters", [](auto& s) -> auto& { return s.dem.static_thickness_diameters; }, 0, 1e4,
           "thickness of the static layer above the fixed one, in the largest grain's diameters (§8.1: 2 mm, ten "
           "0.2 mm grains; thinner lets the flow stand steeper: docs/dem.md)")
          .swept({times(0.5), times(2)}),
      boolean("dem.static_bodies", [](auto& s) -> auto& { return s.dem.static_bodies; },
              "three: static grains stay bodies the flow can push, as §8.1 has them, and pictures stand as all-dynamic's "
              "(false: immovable spheres, 1.4-1.6x fewer body-steps at --scale 0.2, but the flow holds in their notches and "
              "stands steeper: docs/dem.md)"),
      real("dem.static_reach_diameters", [](auto& s) -> auto& { return s.dem.static_reach_diameters; }, 0, 1e6,
           "with dem.static_bodies: a static grain is a body only while a dynamic grain is within this many "
           "largest-grain diameters, otherwise an immovable sphere: faster, steeper piles (0: no limit)"),
      real("dem.simulated_fall_s", [](auto& s) -> auto& { return s.dem.simulated_fall_s; }, 0, 1e6,
           "a falling grain is a body for the last this-many seconds of its fall (at its settling speed; at least its "
           "last 4 diameters, never above its outlet), so grains meet in the water as paper §7 has it; above, its "
           "flight is analytic. 20 simulates the default scene's whole fall at any --scale up to 1 (at full size its slowest "
           "grains fall 690 px in 15 s); 0: analytic, faster, the slow classes of a burst landing after the fast "
           "ones as a layer of their own"),
      real("dem.max_overlap", [](auto& s) -> auto& { return s.dem.max_overlap; }, 0.01, 10,
           "divergence: two grains overlapping by more than this (small-grain diameters) stop the run"),
      real("dem.target_overlap", [](auto& s) -> auto& { return s.dem.target_overlap; }, 0.001, 10,
           "deepest overlap (small-grain diameters) a converged run keeps: past it, the sub-steps double"),
      integer("dem.max_substeps", [](auto& s) -> auto& { return s.dem.max_substeps; }, 1, 256,
              "most sub-steps per step: a stiff run (deep overlaps, energy growing) doubles them up to this (1: never)"),
      real("dem.run_on_s", [](auto& s) -> auto& { return s.dem.run_on_s; }, 0, 1000,
           "simulated seconds the run goes on after it has settled, its outline sampled into the stats (run_on)"),
  });
  section(kRender, false, {
      text("render.background", [](auto& s) -> auto& { return s.render.background; },
           "picture behind the emptied upper part (§10, Fig. 14g); empty: render.background_color"),
      figures_field(),
      boolean("render.symmetric", [](auto& s) -> auto& { return s.render.symmetric; },
              "§10, Fig. 18c: copy the settled sand, flip it vertically and place it over itself"),
      colour("render.background_color", [](auto& s) -> auto& { return s.render.background_color; },
             "colour of the emptied upper part"),
  });
  section(kPipeline, false, {regions_field()});
  return all;
}

}  // namespace

const std::vector<Field>& scene_fields() {
  static const std::vector<Field> fields = make_fields();
  return fields;
}

bool area_key(const std::string& path) {
  const Field* f = find_field(path);
  return f && f->area;
}

ordered_json keys_json() {
  const Scene defaults;
  ordered_json out = ordered_json::array();
  for (const Field& f : scene_fields()) {
    ordered_json k{{"key", f.path}, {"help", f.help}, {"kind", f.kind}, {"default", f.get(defaults)}};
    if (f.lo < f.hi) k["min"] = f.lo, k["max"] = f.hi;
    if (!f.choices.empty()) k["choices"] = f.choices;
    k["scaled"] = f.px;
    ordered_json readers = ordered_json::array();
    for (auto [bit, name] : {std::pair{kPipeline, "pipeline"}, {kLattice, "lattice"}, {kDem, "dem"}, {kLammps, "lammps"}, {kRender, "render"}})
      if (f.readers & bit) readers.push_back(name);
    k["read_by"] = readers;
    k["area"] = f.area;
    if (!f.fit_grid.empty()) k["fit_grid"] = f.fit_grid;
    ordered_json sweep = ordered_json::array();  // validate's points, around the default scene
    for (const SweepPoint& p : f.sweep) {
      const ordered_json v = p.change(f, f.get(defaults), defaults);
      if (!v.is_null() && v != f.get(defaults)) sweep.push_back(sweep_setting(f, p, v).substr(f.path.size()));
    }
    if (!sweep.empty()) k["sweep"] = sweep;
    out.push_back(k);
  }
  return out;
}

}  // namespace sandpic
