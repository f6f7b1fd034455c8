#pragma once
// The one Scene struct: every parameter of the paper with its default here and
// its key, range and help text beside it in scene_fields.cpp.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sandpic {

constexpr int kClasses = 4;  // paper §4.1: grain classes S1..S4

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

enum class InitMethod { Tessellation, Halftone };
enum class TessellationKind { Uniform, Varying, Strips };
enum class SegmentMethod { Ellipses, Explicit, Cells, Sketch, Pattern };
enum class Mode { Lattice, Dem, Lammps };  // lammps: the reference DEM (physics/lammps_simulator.h)
std::string mode_name(Mode m);  // the scene key's word for it
enum class Layers { Three, Bcre, AllDynamic };  // paper §8: layer models of the DEM mode
// Lattice: grains land in the order they reach the pile (settling) or in falling order (release).
enum class LatticeArrival { Settling, Release };

// A line drawn in the window, in px (x right, y down), as its corner points.
using Polyline = std::vector<std::array<double, 2>>;

// An ellipse of the segmentation, in window pixels (x right, y down).
struct EllipseSpec {
  double cx = 0, cy = 0, a = 1, b = 1, angle_deg = 0;
};

// paper §3: "users may further edit colors in the cells". Classes are 1-based
// in scene files (S1..S4), 0-based in code.
struct CellOverride {
  int cell = 0;
  int dominant = 0;
  int secondary = 1;
};

// paper §10, Fig. 16: a figure placed over the sand.
struct Figure {
  std::string mask;   // a picture: its dark pixels (luminance under 128) are the figure
  double x = 0, y = 0, scale = 1;  // the mask's top-left in the window (px) and its size factor
  Polyline polygon;   // or a polygon in window px
};

// paper §10, Fig. 17: an area of the initialization region with its own
// tessellation, colour mix and segmentation (mountains, clouds).
struct Area {
  std::array<double, 4> rect{0, 0, 1e6, 1e6};  // x0, y0, x1, y1 in window px, clipped to the region
  Polyline polygon;    // or, inside rect, only these pixel centres
  std::string preset;  // applied first (its init, segment and grains.proportions keys only)
  // The area's own scene keys (init.*, segment.*, grains.proportions) as
  // (path, JSON text), applied over the scene in this order.
  std::vector<std::pair<std::string, std::string>> settings;
};

struct Scene {
  std::string description;  // free text for people; the pipeline ignores it
  std::string preset;       // paper §9: a base read before the scene's own keys (src/presets.cpp)
  struct Window {
    int width = 1000;  // paper §4.1
    int height = 700;
  } window;
  struct Region {
    int height = 350;  // paper §4.1: initialization region, top of the window
  } region;
  struct Units {
    // One grain per pixel of the region; a pixel is this many mm, so the
    // region's grains packed at `packing` cover about the region's area.
    double mm_per_pixel = 0.18;
    double packing = 0.82;
  } units;
  struct Grains {
    std::array<double, kClasses> density_g_cm3{3.2, 3.2, 2.7, 2.7};  // paper §4.1
    std::array<double, kClasses> diameter_mm{0.2, 0.2, 0.1, 0.1};
    std::array<double, kClasses> proportions{3.0 / 8, 3.0 / 8, 1.0 / 8, 1.0 / 8};
    // C1..C4: dark, heavy S1 at the bottom of a pile reads as rock.
    std::array<Rgb, kClasses> colors{Rgb{36, 40, 66}, Rgb{168, 84, 52}, Rgb{226, 178, 96},
                                     Rgb{246, 240, 226}};
  } grains;
  struct Init {
    InitMethod method = InitMethod::Tessellation;
    std::string image;  // halftone input; loaded only for method=halftone
    TessellationKind tessellation = TessellationKind::Varying;
    double cell_width = 50, cell_height = 35;            // uniform (Fig. 4)
    double row_height_min = 12, row_height_max = 44;     // varying (Fig. 5), strips
    double cell_width_min = 24, cell_width_max = 130;    // varying
    double dominant_share = 0.8;                         // paper §4.4
    std::vector<CellOverride> cell_overrides;
  } init;
  struct Segment {
    SegmentMethod method = SegmentMethod::Ellipses;
    double semi_major_min = 45, semi_major_max = 150;  // top row, bottom row
    double eccentricity_min = 0.45, eccentricity_max = 0.65;
    std::vector<EllipseSpec> ellipses;  // method=explicit
    // paper §5.2, Fig. 7-8: method=sketch places an ellipse under every
    // crossing of an arc-like curve with a ridge line.
    struct Sketch {
      std::vector<Polyline> ridges, arcs;  // window px; or, instead, an image:
      std::string image;                   // strokes of two colours over the region (Fig. 2f)
      Rgb ridge_color{220, 30, 30}, arc_color{30, 160, 60};
      double shrink_per_px = 0.3;      // paper's α: a_i = 0.5 A_m - α P_i(y)
      double semi_major_floor = 12;    // px: a_i never below this (high crossings)
      double bottom_band = 0.25;       // A_m counts the ridges reaching this share of the region's bottom
      bool narrow = true;              // insert the long narrow ellipses (Fig. 7c)
      double narrow_spacing = 1.2;     // ... where crossings along a ridge are farther apart than this x b
    } sketch;
    // paper §9-10, Fig. 18: method=pattern covers the region with full-width
    // rows from the bottom up; each row repeats a unit of two ellipses of
    // different axes along x, rows drawn apart; thin separating rectangles between rows.
    struct Pattern {
      double row_height_min = 30, row_height_max = 60;    // px
      double semi_major_min = 18, semi_major_max = 60;    // px, each ellipse of a unit
      double minor_share_min = 0.55, minor_share_max = 1; // b as a share of half the row height
      double separator = 4;      // px: thin rectangles between rows (0: none)
      int separator_class = 1;   // their grains' class S1..S4 (0: the tessellation's)
    } pattern;
  } segment;
  struct Order {
    double row_tolerance = 20;  // px: centres this close in y share a row (§6)
  } order;
  struct Release {
    double outlet_width_mm = 15;  // paper §7
    double gravity_m_s2 = 9.81;
  } release;
  Mode mode = Mode::Lattice;
  uint64_t seed = 1;
  std::optional<uint64_t> layout_seed;   // null: same as seed
  std::optional<uint64_t> physics_seed;  // null: same as seed
  struct Physics {
    double friction = 0.4;     // paper §7: static = dynamic = 0.4
    double restitution = 0.1;  // paper §7
  } physics;
  struct Lattice {
    double resolution = 1.0;  // height-field columns per pixel
    // tan(angle of repose) = repose_gain * friction, per class (Fig. 9:
    // steeper with friction, bigger grains steeper).
    std::array<double, kClasses> repose_gain{1.45, 1.45, 1.2, 1.2};
    std::optional<std::array<double, kClasses>> repose_deg;  // overrides the gain
    std::array<double, kClasses> runout_px{2, 2, 3, 3};  // extra travel down a slope
    int window_columns = 0;  // non-local rule width; 0: chosen per class
    // Area a grain takes in the lattice's pile as a multiple of grain_area_px:
    // the DEM's piles pack looser than units.packing (calibrate measures it).
    double bulk = 1.0;
    // The DEM's piles end in a loose, rough layer of about the same thickness
    // at every size: the lattice's top 10 px are drawn this much thicker
    // (calibrate fits it with bulk from two pile sizes).
    double surface_px = 0;
    // Bouchaud et al. [24] (paper §8): a rolling grain may be caught by the
    // static surface on its way down: per column slid, with this chance, it
    // stops where the flank is at most trap_deg steeper than its angle of
    // repose (0: grains only stop where the slope is below the angle).
    double trap_rate = 0;
    double trap_deg = 3;
    // paper §7 as the DEM does it: a grain is put in above the pile only
    // where no other is in its way, so a busy outlet's grains queue and land
    // later than Eq. 1 says, in a mixed order. The lattice's stand-in: a
    // landing spot (a pixel column) stays busy this long after a grain lands
    // on it, and a grain due there waits until it is free (settling arrival
    // only; 0: never busy). calibrate --spot fits it.
    double spot_busy_s = 0;
    // The DEM's picture gives each pixel to the nearest grain centre, so where
    // big and small grains mix a small grain shows about twice its share of
    // the area (measured on the default scene at --scale 0.5: 0.51 px a small
    // grain, 1.16 a big one, areas 1:4). Where a column holds more than one
    // share, its deposits are drawn in proportion to area · share, its top
    // kept (the silhouette does not move). calibrate --shares fits it (1: by area).
    std::array<double, kClasses> picture_share{1, 1, 1, 1};
    std::string calibration;  // `sandpic calibrate` output whose "lattice" values replace these
    // paper §7 + the water: grains land in the order they reach the pile, at
    // dem.release_rate and their class's settling speed, as in the DEM.
    LatticeArrival arrival = LatticeArrival::Settling;
  } lattice;
  struct Dem {
    Layers layers = Layers::Three;
    double step_diameters = 0.05;  // most a grain moves in one step, in small-grain diameters
    int solver_iterations = 10;
    double release_rate = 4000;    // grains released per simulated second
    // Rolling resistance μ_r: the torque at a contact is at most μ_r·R_r·N.
    // 0.1 piles verify-dem's full two-size heap (all-dynamic, friction 0.4) at
    // 37° and 34° (seeds 1, 2; docs/notebook/2026-12-04-solver-order.md).
    double rolling_resistance = 0.1;
    bool water = true;             // drag and buoyancy of the device's water
    double water_density_g_cm3 = 1.0;
    double water_viscosity_pa_s = 1.0e-3;
    int cycle_steps = 40;              // paper §8.1: layers updated every 40 steps
    double rest_displacement = 0.01;   // at rest: moved less than this (small-grain diameters) in a cycle
    int patience_cycles = 0;           // at rest this many cycles: static anywhere (0: never)
    double slope_limit_deg = 0;        // paper §8.1's α for the steepest drop θ; 0: from the piles
    double slope_margin_deg = 0;       // α from the piles: the all-dynamic heap angle plus this
    double slope_baseline_diameters = 4;  // θ measured this far to either side (largest grain diameters)
    // paper §8.1: 2 mm, ten of its 0.2 mm grains. In grains, so that --scale
    // (coarser sand, docs/cli.md) keeps the band as many grains thick.
    double static_thickness_diameters = 10;
    bool static_bodies = true;         // paper §8.1: static grains stay in the simulation (docs/dem.md)
    double static_reach_diameters = 0;  // and are bodies only this near the flow (largest diameters; 0: always)
    double simulated_fall_s = 20;      // paper §7: a body for this long before it lands (from its outlet at most)
    double max_overlap = 1.0;          // divergence: overlap beyond this (small-grain diameters)
    // Stiffness (physics/stiffness.h): an overlap past target_overlap
    // (small-grain diameters), or bodies twice as fast as settling, doubles
    // the sub-steps of each step's water and Bullet step, up to
    // max_substeps; past max_overlap at the most, the run has diverged.
    double target_overlap = 0.05;
    int max_substeps = 16;
    // Simulated seconds the run goes on after it has settled, its outline
    // sampled every 0.25 s into the stats (verify-dem: does a pile creep?).
    double run_on_s = 0;
  } dem;
  struct Render {
    std::string background;  // image for the emptied upper part (§10, Fig. 14g)
    Rgb background_color{248, 246, 240};
    std::vector<Figure> figures;
    // paper §10, Fig. 18c: the settled sand copied, flipped vertically and
    // placed over itself, mirrored about the top of the sand.
    bool symmetric = false;
  } render;
  std::vector<Area> regions;  // paper §10, Fig. 17; a pixel in none keeps the scene's own settings

  std::string base_dir;  // folder of the scene file; relative paths start here

  uint64_t layout() const { return layout_seed.value_or(seed); }
  uint64_t physics_rng() const { return physics_seed.value_or(seed); }
  std::string resolve(const std::string& path) const;
};

// Grain geometry in pixels, derived from the scene's mm values.
double px_per_mm(const Scene& s);
// Area a grain of class k takes in a pile, in px² (diameter² · π/4 / packing):
// a big grain covers four times a small one, in both modes.
double grain_area_px(const Scene& s, int k);
double grain_diameter_px(const Scene& s, int k);
// paper §7, Fig. 9: the angle of repose of class k that the lattice piles
// at, and the calibration and validation start from: tan θ_k =
// lattice.repose_gain_k · physics.friction, unless lattice.repose_deg sets θ_k.
double repose_angle_deg(const Scene& s, int k);
// dem.layers as scene files spell it: three, bcre, all-dynamic.
std::string layers_name(Layers l);

}  // namespace sandpic
