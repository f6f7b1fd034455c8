#pragma once
// A height field of columns on which grains settle one at a time, after the
// height-field and cellular-automaton models of granular piles the paper
// cites ([20]-[23]). Heights are continuous (px), so a grain adds exactly its
// area: a big grain raises its column four times as much as a small one.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace sandpic {

// The slope rule of one grain class. A grain slides on while the drop over
// the next k columns exceeds k·drop_per_column for some k <= window: the
// non-local form lets a pixel grid hold any angle, not just the 45° of a
// one-neighbour rule, since a grain's own height step is spread over k.
struct SlopeRule {
  double drop_per_column = 0;  // tan(angle of repose) · column width
  int window = 1;              // columns looked ahead
  int runout = 0;              // columns it keeps going down once stable
  double trap_rate = 0;        // chance per column slid of being caught on the flank
  double trap_drop_per_column = 0;  // steepest slope a caught grain may rest on
  bool operator==(const SlopeRule&) const = default;
};

struct Deposit {
  float top;    // height of the deposit's upper edge, px above the floor
  uint8_t cls;  // grain class
};

class HeightField {
 public:
  static constexpr int kMaxWindow = 64;

  HeightField(int columns, double column_width_px, double ceiling_px, std::vector<SlopeRule> rules);

  int columns() const { return columns_; }
  // Outside the window (the walls) the height is infinite.
  double height(int c) const { return h_[size_t(c + kPad)]; }
  double max_height() const;

  // The column where a grain of rule `r` dropped on column c comes to rest.
  // Ties on a peak are broken by (seed, id), never by call order.
  int settle(int c, int r, uint64_t seed, uint64_t id) const;
  // The nearest column to c that can take `rise` more px; -1 if none.
  int room_near(int c, double rise) const;
  // Adds a grain's area to column c; returns the height of its centre.
  double deposit(int c, uint8_t cls, double area_px);

  // Class of the deposit at each pixel centre, for a window of the given size
  // (CV_8U, `empty` where no sand lies). `surface_px` > 0 draws each column's
  // top kLooseLayerPx of sand stretched by that much: the DEM's piles end in a
  // loose, rough layer about as thick at every pile size (lattice.surface_px).
  // `share[cls]` (empty: all 1) redraws a column's deposits in proportion to
  // rise · share, its top kept: the DEM's picture gives each pixel to the
  // nearest grain centre, so where big and small grains mix a small grain
  // shows larger than its area (lattice.picture_share). A column of one class
  // is drawn as before.
  static constexpr double kLooseLayerPx = 10;
  cv::Mat class_map(int width, int height, uint8_t empty, double surface_px = 0,
                    const std::vector<double>& share = {}) const;

 private:
  static constexpr int kPad = kMaxWindow + 1;
  static constexpr int kShortWindow = 8;  // recomputed whole on each deposit (refresh)
  // Per rule, which columns a grain cannot rest on because the slope toward
  // +x (side 0) or -x (side 1) is too steep; kept up to date by deposit(),
  // so a slide is a scan for the next clear bit.
  struct Slopes {
    SlopeRule rule;
    std::vector<uint64_t> steep[2];
  };
  bool unstable(int c, int dir, const SlopeRule& rule) const;
  bool too_steep(int c, int dir, double drop_per_column, int window) const;
  int slide(const Slopes& s, int c, int dir, uint64_t seed, uint64_t id, int& draws, bool& caught) const;
  double excess(int c, int dir, const SlopeRule& rule) const;
  bool steep(const Slopes& s, int c, int dir) const;
  int next_resting(const Slopes& s, int c, int dir) const;
  void refresh(Slopes& s, int c);
  void recompute(Slopes& s, int side, int first, int count);

  std::vector<double> h_;  // kPad walls, the columns, kPad walls
  int columns_;
  std::vector<std::vector<Deposit>> stacks_;
  std::vector<Slopes> slopes_;
  double width_, ceiling_;
};

}  // namespace sandpic
