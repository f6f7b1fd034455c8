#include "src/grain_table.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "src/errors.h"
#include "src/release.h"

namespace sandpic {

namespace {
constexpr const char* kHeader = "id,class,unit,order,release_x,x,y";
}

std::string grain_table_csv(const Scene& s, const GrainSet& g, const Segmentation& seg, const FallingOrder& order,
                            const std::vector<float>& x, const std::vector<float>& y) {
  // Every grain of the region is in a unit (seg.unit_of) and released once.
  const size_t n = seg.unit_of.size();
  std::vector<int64_t> rank(n);
  for (size_t i = 0; i < order.grain.size(); ++i) rank[size_t(order.grain[i])] = int64_t(i);
  const ReleaseModel model = release_model(s);
  std::vector<Outlet> outlets;
  for (const Unit& u : seg.units) outlets.push_back(outlet(model, u));
  std::string out = std::string(kHeader) + "\n";
  out.reserve(n * 40);
  char line[160];
  for (size_t id = 0; id < n; ++id) {
    const int32_t unit = seg.unit_of[id];
    const double release_x = exit_x(model, outlets[size_t(unit)], int32_t(id));
    std::snprintf(line, sizeof line, "%zu,%d,%d,%lld,%.3f,%.3f,%.3f\n", id, int(g.cls[id]), unit,
                  static_cast<long long>(rank[id]), release_x, double(x[id]), double(y[id]));
    out += line;
  }
  return out;
}

std::vector<GrainRow> parse_grain_table(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kHeader)
    throw InputError(name + ": not a grain table (render --grains): the first line must be '" + kHeader + "'");
  std::vector<GrainRow> rows;
  for (int64_t number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    GrainRow r;
    long long order = 0;
    int used = 0;
    if (std::sscanf(line.c_str(), "%d,%d,%d,%lld,%lf,%lf,%lf%n", &r.id, &r.cls, &r.unit, &order, &r.release_x, &r.x,
                    &r.y, &used) != 7 ||
        size_t(used) != line.size() || r.id < 0 || r.cls < 0 || r.cls > 3 || r.unit < 0 || order < 0 ||
        !std::isfinite(r.release_x) || !std::isfinite(r.x) || !std::isfinite(r.y))
      throw InputError(name + ": line " + std::to_string(number) + " is not 'id,class,unit,order,release_x,x,y'");
    r.order = order;
    rows.push_back(r);
  }
  if (rows.empty()) throw InputError(name + ": no grains");
  return rows;
}

}  // namespace sandpic
