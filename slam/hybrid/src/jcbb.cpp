// SPDX-License-Identifier: MIT
#include "jcbb.hpp"

#include <Eigen/Cholesky>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <stdexcept>

namespace lookahead::slam::hybrid {
namespace {

class Search {
 public:
  Search(int items, const std::vector<PairingCandidate>& c, const Eigen::MatrixXd& p, double confidence, int max_nodes)
      : items_(items),
        candidates_(c),
        p_(p),
        confidence_(confidence),
        max_nodes_(max_nodes),
        by_item_(static_cast<std::size_t>(items)),
        gates_(2 * static_cast<std::size_t>(items) + 1) {
    // The joint gate for every dimension (2 per pair), once: a quantile is an iterative inversion.
    for (std::size_t m = 1; m < gates_.size(); ++m) gates_[m] = chi2_quantile(static_cast<int>(m), confidence);
    for (std::size_t k = 0; k < c.size(); ++k) by_item_[static_cast<std::size_t>(c[k].item)].push_back(k);
    // H_k P once per candidate: a node then costs O(m^2 n) for its m pairs, not O(m n^2).
    hp_.reserve(c.size());
    for (const PairingCandidate& k : c) hp_.push_back(k.jacobian * p);
    best_.target_of.assign(static_cast<std::size_t>(items), -1);
  }

  JcbbResult run() {
    std::vector<std::size_t> chosen;
    recurse(0, chosen, 0.0);
    best_.nodes = nodes_;
    return best_;
  }

 private:
  // Joint NIS of the chosen candidates; infinity when not jointly compatible.
  double joint_nis(const std::vector<std::size_t>& chosen) const {
    const Eigen::Index m = 2 * static_cast<Eigen::Index>(chosen.size());
    Eigen::VectorXd nu(m);
    Eigen::MatrixXd s(m, m);
    for (std::size_t a = 0; a < chosen.size(); ++a) {
      const PairingCandidate& ca = candidates_[chosen[a]];
      const Eigen::Index at = 2 * static_cast<Eigen::Index>(a);
      nu.segment<2>(at) = ca.nu;
      for (std::size_t b = 0; b <= a; ++b) {
        const Eigen::Index bt = 2 * static_cast<Eigen::Index>(b);
        s.block<2, 2>(at, bt) = hp_[chosen[a]] * candidates_[chosen[b]].jacobian.transpose();
        s.block<2, 2>(bt, at) = s.block<2, 2>(at, bt).transpose();
      }
      s.block<2, 2>(at, at) += ca.noise;
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(s);
    const double nis = nu.dot(ldlt.solve(nu));
    return nis <= gates_[static_cast<std::size_t>(m)] ? nis : INFINITY;
  }

  // `nis` is the joint NIS of `chosen`. Adding pairings never lowers a joint NIS (the
  // smaller set's S is a principal submatrix of the larger's), so a branch that can at
  // best tie the most pairings found, and already has the larger NIS, cannot win: it is
  // cut. The result is the same as the exhaustive search; dense maps with many tied
  // hypotheses no longer expand them all.
  void recurse(int item, std::vector<std::size_t>& chosen, double nis) {
    const int have = static_cast<int>(chosen.size());
    const int reachable = have + (items_ - item);
    if (reachable < best_.pairings || (reachable == best_.pairings && nis >= best_.nis)) return;
    if (++nodes_ > max_nodes_) {
      best_.search_truncated = true;
      return;
    }
    if (item == items_) {
      record(chosen, nis);
      return;
    }
    for (std::size_t k : by_item_[static_cast<std::size_t>(item)]) {
      if (target_taken(chosen, candidates_[k].target)) continue;
      chosen.push_back(k);
      const double with = joint_nis(chosen);
      if (std::isfinite(with)) recurse(item + 1, chosen, with);
      chosen.pop_back();
    }
    recurse(item + 1, chosen, nis);  // this item unpaired
  }

  bool target_taken(const std::vector<std::size_t>& chosen, int target) const {
    for (std::size_t k : chosen) {
      if (candidates_[k].target == target) return true;
    }
    return false;
  }

  void record(const std::vector<std::size_t>& chosen, double nis) {
    best_.target_of.assign(static_cast<std::size_t>(items_), -1);
    for (std::size_t k : chosen) best_.target_of[static_cast<std::size_t>(candidates_[k].item)] = candidates_[k].target;
    best_.pairings = static_cast<int>(chosen.size());
    best_.nis = nis;
  }

  int items_;
  const std::vector<PairingCandidate>& candidates_;
  const Eigen::MatrixXd& p_;
  double confidence_;
  std::vector<double> gates_;  ///< gates_[m]: the `confidence` chi-square quantile, m dof
  int max_nodes_;
  int nodes_ = 0;
  std::vector<std::vector<std::size_t>> by_item_;
  std::vector<Eigen::MatrixXd> hp_;  ///< per candidate: H P (2 x n)
  JcbbResult best_;
};

}  // namespace

double chi2_quantile(int dof, double confidence) {
  if (dof < 1) throw std::invalid_argument("chi2_quantile: dof must be >= 1");
  if (!(confidence > 0 && confidence < 1)) {
    throw std::invalid_argument("chi2_quantile: confidence must be in (0, 1)");
  }
  return boost::math::quantile(boost::math::chi_squared(dof), confidence);
}

JcbbResult jcbb(int items, const std::vector<PairingCandidate>& candidates, const Eigen::MatrixXd& covariance,
                double confidence, int max_nodes) {
  return Search(items, candidates, covariance, confidence, max_nodes).run();
}

}  // namespace lookahead::slam::hybrid
