#pragma once
// The statistics every benchmark and check reports, one implementation each.
#include <vector>

namespace sandpic {

// The median of the finite values (NaN if none): the benchmarks' statistic.
double median(std::vector<double> v);
// The mean (NaN if empty).
double mean(const std::vector<double>& v);
// The sample standard deviation (0 for fewer than two values): the seed spread.
double spread(const std::vector<double>& v);

}  // namespace sandpic
