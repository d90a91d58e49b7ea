// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_statistics.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lookahead::exploration {

double mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

double sample_std(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  const double m = mean(values);
  double ss = 0.0;
  for (const double v : values) ss += (v - m) * (v - m);
  return std::sqrt(ss / static_cast<double>(values.size() - 1));
}

double student_t_two_sided_p(double t, double df) {
  if (!(df > 0)) throw std::invalid_argument("student_t_two_sided_p needs df > 0");
  if (std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(t)) return 0.0;
  const boost::math::students_t dist(df);
  return 2.0 * boost::math::cdf(boost::math::complement(dist, std::abs(t)));
}

double student_t_quantile(double p, double df) {
  if (!(df > 0) || !(p > 0 && p < 1)) {
    throw std::invalid_argument("student_t_quantile needs df > 0 and p in (0, 1)");
  }
  return boost::math::quantile(boost::math::students_t(df), p);
}

WelchResult welch_t_test(const std::vector<double>& a, const std::vector<double>& b) {
  WelchResult r;
  if (a.size() < 2 || b.size() < 2) {
    r.why = "fewer than 2 values in a sample";
    return r;
  }
  const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
  const double sa = sample_std(a), sb = sample_std(b);
  const double va = sa * sa / na, vb = sb * sb / nb;  // squared standard errors
  r.mean_difference = mean(a) - mean(b);
  if (va + vb == 0.0) {
    r.why = "no variance in either sample";
    return r;
  }
  r.t = r.mean_difference / std::sqrt(va + vb);
  // Welch-Satterthwaite: df = (va + vb)^2 / (va^2 / (na - 1) + vb^2 / (nb - 1)).
  r.df = (va + vb) * (va + vb) / (va * va / (na - 1) + vb * vb / (nb - 1));
  r.p = student_t_two_sided_p(r.t, r.df);
  r.defined = true;
  return r;
}

}  // namespace lookahead::exploration

namespace lookahead::exploration {

WelchResult paired_t_test(const std::vector<double>& a, const std::vector<double>& b) {
  WelchResult r;
  if (a.size() != b.size() || a.size() < 2) {
    r.why = "fewer than 2 pairs";
    return r;
  }
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  r.mean_difference = mean(d);
  const double s = sample_std(d);
  if (s == 0.0) {
    r.why = "the differences do not vary";
    return r;
  }
  const double n = static_cast<double>(d.size());
  r.t = r.mean_difference / (s / std::sqrt(n));
  r.df = n - 1;
  r.p = student_t_two_sided_p(r.t, r.df);
  r.defined = true;
  return r;
}

}  // namespace lookahead::exploration
