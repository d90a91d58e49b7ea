// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_statistics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lookahead::exploration {
namespace {

constexpr double kTiny = 1e-300;    // keeps Lentz's quotients away from division by zero
constexpr double kEpsilon = 1e-15;  // relative change at which the fraction has converged
constexpr int kMaxTerms = 10000;    // converges in O(sqrt(max(a, b))) terms; a safety net

// The continued fraction of A&S 26.5.8, 1 / (1 + d1 / (1 + d2 / (1 + ...))), with
//   d_{2m+1} = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)),
//   d_{2m}   =  m (b - m) x / ((a + 2m - 1)(a + 2m)),
// evaluated forwards by the modified Lentz method. It converges fast for x < (a+1)/(a+b+2).
double beta_fraction(double a, double b, double x) {
  // Lentz on f = b0 + a1 / (b1 + a2 / (b2 + ...)) with b0 = 0, a1 = 1, a_{j+1} = d_j and
  // every b_j = 1; f and C start at "tiny" because b0 = 0.
  double f = kTiny, c = kTiny, d = 0.0;
  const auto step = [&](double numerator) {
    d = 1.0 + numerator * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1.0 + numerator / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = c * d;
    f *= delta;
    return std::abs(delta - 1.0) < kEpsilon;
  };
  step(1.0);
  for (int m = 0; m < kMaxTerms; ++m) {
    if (step(-(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1)))) break;  // d_{2m+1}
    const double n = m + 1;
    if (step(n * (b - n) * x / ((a + 2 * n - 1) * (a + 2 * n)))) break;  // d_{2n}
  }
  return f;  // after kMaxTerms only for absurd a, b; f is then still close
}

}  // namespace

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

double regularized_incomplete_beta(double a, double b, double x) {
  if (!(a > 0) || !(b > 0) || !(x >= 0 && x <= 1)) {
    throw std::invalid_argument("regularized_incomplete_beta needs a, b > 0 and x in [0, 1]");
  }
  if (x == 0.0 || x == 1.0) return x;
  // I_x(a, b) = 1 - I_{1-x}(b, a): evaluate the side on which the fraction converges.
  if (x > (a + 1) / (a + b + 2)) return 1.0 - regularized_incomplete_beta(b, a, 1.0 - x);
  const double log_beta = std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b);
  const double front = std::exp(a * std::log(x) + b * std::log1p(-x) - log_beta) / a;
  return front * beta_fraction(a, b, x);
}

double student_t_two_sided_p(double t, double df) {
  if (!(df > 0)) throw std::invalid_argument("student_t_two_sided_p needs df > 0");
  if (std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(t)) return 0.0;
  // P(|T| >= |t|) = I_{df / (df + t^2)}(df / 2, 1 / 2).
  return regularized_incomplete_beta(df / 2.0, 0.5, df / (df + t * t));
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
