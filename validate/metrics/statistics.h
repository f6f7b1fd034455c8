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
// How far apart the means of two sets of seeds may lie when nothing but the
// seed changes between them: Student's two-sample test at 95%,
// t(0.975, n_a + n_b - 2) · s_p · √(1/n_a + 1/n_b), with s_p the pooled
// spread. The mean of n seeds itself scatters by s/√n, and a spread read off
// two seeds is itself rough: one spread between two means of two seeds is
// exceeded a third of the time by chance alone. NaN with fewer than 3 runs.
double mean_shift_limit(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace sandpic
