// SPDX-License-Identifier: MIT
// The statistics of a study: sample mean and standard deviation, and Welch's unequal-
// variance t-test (Welch, "The generalization of 'Student's' problem when several different
// population variances are involved", Biometrika 34, 1947) with the Welch-Satterthwaite
// degrees of freedom. The Student t distribution is Boost.Math's.
#pragma once

#include <string>
#include <vector>

namespace lookahead::exploration {

[[nodiscard]] double mean(const std::vector<double>& values);  ///< 0 for no values
/// Sample standard deviation (divides by n - 1); 0 for fewer than two values.
[[nodiscard]] double sample_std(const std::vector<double>& values);

/// P(|T| >= |t|) for T ~ Student t with `df` > 0 degrees of freedom (df need not be whole).
[[nodiscard]] double student_t_two_sided_p(double t, double df);
/// The p-quantile of Student's t with `df` > 0 degrees of freedom, p in (0, 1) (for
/// confidence intervals: student_t_quantile(0.975, n - 1) for 95 %).
[[nodiscard]] double student_t_quantile(double p, double df);

struct WelchResult {
  bool defined = false;  ///< false: `why` says what is missing (too few runs, no variance)
  std::string why;
  double t = 0.0;                ///< (mean_a - mean_b) / sqrt(s_a^2 / n_a + s_b^2 / n_b)
  double df = 0.0;               ///< Welch-Satterthwaite degrees of freedom
  double p = 1.0;                ///< two-sided
  double mean_difference = 0.0;  ///< mean_a - mean_b
};

/// Welch's two-sided t-test of equal means. Needs two values per sample and a non-zero
/// variance in at least one; otherwise `defined` is false (an expected outcome of a study in
/// which a strategy rarely reaches its goal, not an error).
[[nodiscard]] WelchResult welch_t_test(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace lookahead::exploration

namespace lookahead::exploration {

/// The paired t-test of equal means on the differences d_i = a_i - b_i (same world and seed,
/// two strategies): t = mean(d) / (std(d) / sqrt(n)), n - 1 degrees of freedom (Student,
/// "The probable error of a mean", Biometrika 6, 1908). Needs a.size() == b.size() >= 2 and
/// differences that vary; otherwise `defined` is false and `why` says what is missing.
[[nodiscard]] WelchResult paired_t_test(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace lookahead::exploration
