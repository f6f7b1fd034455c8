// The initialization stage (paper §4): the region's grains by tessellation
// and filling or by halftoning, the thin rectangles of a regular pattern
// (§10, Fig. 18) painted, and every area of the region (Fig. 17) made by its
// own scene.
#include "src/init/init.h"
#include "src/regions.h"
#include "src/scene_file.h"

namespace sandpic {

namespace {

Initialization initialize_one(const Scene& s) {
  Initialization init;
  if (s.init.method == InitMethod::Halftone) {
    cv::Mat img = read_image(s.resolve(s.init.image), "init.image");
    init.input = luminance(img, s.window.width, s.region.height);
    init.grains = halftone(s, init.input);
  } else {
    init.tessellation = tessellate(s);
    init.grains = empty_region(s);
    fill_cells(s, init.tessellation, init.grains);
  }
  paint_separators(s, init.grains);
  return init;
}

}  // namespace

Initialization initialize(const Scene& s) {
  Initialization init = initialize_one(s);
  const cv::Mat map = area_map(s);
  for (size_t i = 0; i < s.regions.size(); ++i) {
    // The area is a scene of its rectangle's size, placed at the rectangle.
    const cv::Rect r = area_rect(s, i);
    Scene a = area_scene(s, i);
    a.window.width = r.width, a.region.height = r.height;
    const Initialization part = initialize_one(a);
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x)
        if (map.at<uint8_t>(r.y + y, r.x + x) == i + 1)
          init.grains.cls[size_t(r.y + y) * init.grains.width + (r.x + x)] = part.grains.cls[size_t(y) * r.width + x];
    for (Cell c : part.tessellation.cells) {
      c.x0 += r.x, c.x1 += r.x, c.y0 += r.y, c.y1 += r.y;
      c.area = int(i + 1);
      init.tessellation.cells.push_back(c);
    }
  }
  return init;
}

}  // namespace sandpic
