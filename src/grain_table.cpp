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
  const size_t n = size_t(g.size());
  std::vector<int32_t> unit(n, -1);
  std::vector<int64_t> rank(n, -1);
  for (size_t u = 0; u + 1 < order.unit_begin.size(); ++u)
    for (int64_t i = order.unit_begin[u]; i < order.unit_begin[u + 1]; ++i) {
      const size_t id = size_t(order.grain[size_t(i)]);
      unit[id] = int32_t(u), rank[id] = i;
    }
  const ReleaseModel model = release_model(s);
  std::vector<Outlet> outlets;
  for (const Unit& u : seg.units) outlets.push_back(outlet(model, u));
  std::string out = std::string(kHeader) + "\n";
  out.reserve(n * 40);
  char line[160];
  for (size_t id = 0; id < n; ++id) {
    if (rank[id] < 0) continue;  // not released: no grain there
    const double release_x = exit_x(model, outlets[size_t(unit[id])], int32_t(id));
    std::snprintf(line, sizeof line, "%zu,%d,%d,%lld,%.3f,%.3f,%.3f\n", id, int(g.cls[id]), unit[id],
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
