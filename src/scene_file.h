#pragma once
// Scene files (JSON): parse once into the Scene struct, with every key's type,
// range and default declared in one registry (scene_fields.cpp). A key nobody
// reads is an error that names it and suggests the nearest valid key.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "src/errors.h"
#include "src/scene.h"

namespace sandpic {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

// Which stages read a key: the shared pipeline (paper §4-7, every mode), one
// backend, or rendering (§10, every mode).
enum Reader : unsigned { kPipeline = 1, kLattice = 2, kDem = 4, kRender = 8, kLammps = 16 };

struct Field;

// A point of validate's sweep (error against run time): the key's value
// changed one way, from its value in the scene (null: no such point for this
// scene; the value itself: none either).
struct SweepPoint {
  std::string name;  // shown after the key ("+5", "*2+2"); "": "=" and the new value
  std::function<ordered_json(const Field& f, const ordered_json& value, const Scene& s)> change;
};
// The usual points: a number (or each of a class's) times f or plus d,
// within the key's range (an integer rounded down); the value v.
SweepPoint times(double f);
SweepPoint plus(double d);
SweepPoint to(ordered_json v, std::string name = "");
// A sweep point's setting as reports name it: "lattice.bulk=0.95",
// "lattice.picture_share=1,1,1.5,1.5", "lattice.repose_deg+5".
std::string sweep_setting(const Field& f, const SweepPoint& p, const ordered_json& changed);

// One scene key, declared once (src/scene_fields.cpp); everything else about
// keys derives from this: the scene file, --set, --scale, areas, the digest,
// unread keys, `scene --keys`, validate's sweep, docs/scene-reference.md and
// the studio's /api/keys.
struct Field {
  std::string path;  // "segment.eccentricity_max"
  std::string help;
  bool px = false;  // a length in pixels: multiplied by --scale
  std::function<ordered_json(const Scene&)> get;
  std::function<void(Scene&, const json&)> set;  // throws InputError naming path
  std::string kind;                     // number, integer, boolean, choice, text, seed, per_class, colour, list
  double lo = 0, hi = 0;                // a number's range (lo == hi: none)
  std::vector<std::string> choices;     // a choice's names
  unsigned readers = 0;                 // which stages read it (Reader bits; 0: its section's, make_fields)
  bool area = false;                    // an area of the region (regions[i]) may set it (paper §10, Fig. 17)
  // A lattice setting fitted to the DEM by trying values: `calibrate --fit
  // KEY` runs the whole fit once per value (the scene's own first) and keeps
  // the best. Empty: not fitted this way.
  std::vector<double> fit_grid;
  // The values validate's sweep tries, one at a time (a lattice key in its
  // lattice sweep, a DEM key in its DEM sweep). Empty: not swept.
  std::vector<SweepPoint> sweep;

  Field(std::string path, std::string help, bool px, std::function<ordered_json(const Scene&)> get,
        std::function<void(Scene&, const json&)> set)
      : path(std::move(path)), help(std::move(help)), px(px), get(std::move(get)), set(std::move(set)) {}

  Field& read_by(unsigned r) { return readers = r, *this; }
  Field& in_area() { return area = true, *this; }
  Field& fitted(std::vector<double> grid) { return fit_grid = std::move(grid), *this; }
  Field& swept(std::vector<SweepPoint> points) { return sweep = std::move(points), *this; }
};

const std::vector<Field>& scene_fields();

Scene load_scene(const std::string& path);
// What load_scene does once the file is read: `text` parsed and applied, errors
// naming `name`, relative paths starting at `base_dir` (tests/fuzz feeds it
// arbitrary bytes without a file).
Scene scene_from_text(const std::string& text, const std::string& name, const std::string& base_dir);
void apply_json(Scene& s, const json& doc);
void apply_setting(Scene& s, const std::string& assignment);  // "key.path=value"
void apply_scale(Scene& s, double factor);
void validate(const Scene& s);  // checks that involve several keys
ordered_json to_json(const Scene& s);
// 16 hex digits naming every value the scene's own mode reads (not its
// description, not the other backend's section, not the contents of files
// it names): two runs with one digest and seed give one picture. validate
// keeps a run while its digest holds.
std::string scene_digest(const Scene& s);
// Whether a run in mode m reads the key: the lattice's keys only the lattice,
// the DEM's only the DEM but for the device's release rate and water (the
// lattice lands grains by their settling, lattice.arrival); the others both.
bool read_in_mode(const std::string& path, Mode m);
bool read_in_mode(const Field& f, Mode m);
// Whether an area (regions[i]) may set the key.
bool area_key(const std::string& path);
// Every key as the studio builds its controls from it (/api/keys): key, help,
// kind, default, min, max, choices, scaled, read_by, area.
ordered_json keys_json();
// The keys s's mode never reads among `set_keys` (given with --set) and those
// s holds at other than their default (as pbrt reports unused parameters).
std::vector<std::string> unread_keys(const Scene& s, const std::vector<std::string>& set_keys);
// The scene with lattice.calibration's "lattice" values applied (itself when
// it names no file). Read by the lattice mode only: a DEM run never opens it.
Scene with_calibration(const Scene& s);
std::string nearest_key(const std::string& path);
const Field* find_field(const std::string& path);  // nullptr: no such key
// paper §10, Fig. 17: the scene area i of s.regions is made with: s's keys,
// then the area's preset (its init, segment and grains.proportions keys) and
// its own keys, no areas of its own, and a layout seed of its own.
Scene area_scene(const Scene& s, size_t i);
// "scene key 'regions[0].segment.x': ..." from "scene key 'segment.x': ...".
std::string with_path_prefix(const InputError& e, const std::string& prefix);

}  // namespace sandpic
