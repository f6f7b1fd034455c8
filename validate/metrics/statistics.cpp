#include "validate/metrics/statistics.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>

namespace sandpic {

double median(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double mean(const std::vector<double>& v) {
  return v.empty() ? NAN : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

double spread(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  const double m = mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / double(v.size() - 1));
}

double mean_shift_limit(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t na = a.size(), nb = b.size();
  if (na < 1 || nb < 1 || na + nb < 3) return NAN;
  // Student's t at 0.975 for 1-30 degrees of freedom; above, the last
  // (slightly wide of the 1.96 limit).
  static constexpr double kT975[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                     2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                     2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  const size_t dof = na + nb - 2;
  const double t = kT975[std::min(dof, std::size(kT975)) - 1];
  const double sa = spread(a), sb = spread(b);
  const double pooled = std::sqrt((double(na - 1) * sa * sa + double(nb - 1) * sb * sb) / double(dof));
  return t * pooled * std::sqrt(1.0 / double(na) + 1.0 / double(nb));
}

}  // namespace sandpic
