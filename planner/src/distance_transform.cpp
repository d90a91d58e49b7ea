// SPDX-License-Identifier: MIT
#include "distance_transform.hpp"

#include <cstddef>

namespace lookahead::planner::detail {
namespace {

// One 1D pass (the paper's DT(f)): f holds n samples with stride `stride` starting at
// `first`; they are replaced by min_q ((p - q)^2 + f(q)). v, z and d are scratch buffers.
void transform_line(double* f, int n, std::ptrdiff_t stride, std::vector<int>& v, std::vector<double>& z,
                    std::vector<double>& d) {
  const auto at = [&](int q) { return f[q * stride]; };
  // Where the parabolas rooted at q and p intersect (the paper's s).
  const auto intersect = [&](int q, int p) { return ((at(q) + q * q) - (at(p) + p * p)) / (2.0 * (q - p)); };
  int first = 0;
  while (first < n && at(first) >= kNoSeed) ++first;
  if (first == n) return;  // no seed on this line: everything stays kNoSeed
  int k = 0;               // index of the rightmost parabola of the lower envelope
  v[0] = first;
  z[0] = -kNoSeed;
  z[1] = kNoSeed;
  for (int q = first + 1; q < n; ++q) {
    if (at(q) >= kNoSeed) continue;  // +infinity never joins the envelope (and inf - inf is NaN)
    double s = intersect(q, v[static_cast<std::size_t>(k)]);
    while (s <= z[static_cast<std::size_t>(k)]) {  // stops at k = 0, where z = -infinity
      --k;
      s = intersect(q, v[static_cast<std::size_t>(k)]);
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k) + 1] = kNoSeed;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[static_cast<std::size_t>(k) + 1] < q) ++k;
    const int p = v[static_cast<std::size_t>(k)];
    d[static_cast<std::size_t>(q)] = (q - p) * static_cast<double>(q - p) + at(p);
  }
  for (int q = 0; q < n; ++q) f[q * stride] = d[static_cast<std::size_t>(q)];
}

}  // namespace

std::vector<double> squared_distance_transform(const std::vector<std::uint8_t>& seed, int width, int height) {
  std::vector<double> f(seed.size());
  for (std::size_t i = 0; i < seed.size(); ++i) f[i] = seed[i] ? 0.0 : kNoSeed;
  const int longest = width > height ? width : height;
  std::vector<int> v(static_cast<std::size_t>(longest) + 1);
  std::vector<double> z(static_cast<std::size_t>(longest) + 2);
  std::vector<double> d(static_cast<std::size_t>(longest) + 1);
  for (int x = 0; x < width; ++x) transform_line(&f[static_cast<std::size_t>(x)], height, width, v, z, d);
  for (int y = 0; y < height; ++y) {
    transform_line(&f[static_cast<std::size_t>(y) * static_cast<std::size_t>(width)], width, 1, v, z, d);
  }
  return f;
}

}  // namespace lookahead::planner::detail
