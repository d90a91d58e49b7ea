// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_tables.hpp"

#include <fmt/format.h>

#include <map>

#include "lookahead/exploration/study_report.hpp"
#include "lookahead/exploration/study_statistics.hpp"

namespace lookahead::exploration {
namespace {

constexpr std::size_t k95 = 1;  // index of the 95 % milestone in MissionSummary::milestones
const char* const kStatuses[] = {"coverage_reached", "done", "trapped", "time_limit", "collision"};

std::string mean_std(const std::vector<double>& v, int decimals) {
  if (v.empty()) return "-";
  if (v.size() == 1) return fmt::format("{:.{}f}", v[0], decimals);
  return fmt::format("{:.{}f} +- {:.{}f}", mean(v), decimals, sample_std(v), decimals);
}

std::string share(std::size_t k, std::size_t n) {
  return fmt::format("{}/{} ({:.0f} %)", k, n, n ? 100.0 * static_cast<double>(k) / static_cast<double>(n) : 0.0);
}

bool reached_goal(const StudyRunResult& r) { return r.summary.status == "coverage_reached"; }

std::pair<std::vector<double>, std::vector<double>> to_95(const std::vector<const StudyRunResult*>& runs) {
  std::pair<std::vector<double>, std::vector<double>> out;
  for (const StudyRunResult* r : runs) {
    const Milestone& m = r->summary.milestones[k95];
    if (!m.reached) continue;
    out.first.push_back(m.time);
    out.second.push_back(m.path_length);
  }
  return out;
}

std::vector<std::string> test_row(const std::string& a, const std::string& b, const char* measure,
                                  const WelchResult& r) {
  if (!r.defined) return {a, b, measure, "n/a: " + r.why, "", "", ""};
  return {a,
          b,
          measure,
          fmt::format("{:.2f}", r.mean_difference),
          fmt::format("{:.3f}", r.t),
          fmt::format("{:.2f}", r.df),
          fmt::format("{:.4f}", r.p)};
}

// Times to 95 % of `strategy` on `world` by seed, for the runs that reached it.
std::map<std::uint64_t, double> times_by_seed(const StudySpec& spec, const StudyResult& result, std::size_t world,
                                              const std::string& strategy) {
  std::map<std::uint64_t, double> out;
  for (const StudyRunResult* r : runs_of(spec, result, world, strategy)) {
    if (r->summary.milestones[k95].reached) out[r->summary.seed] = r->summary.milestones[k95].time;
  }
  return out;
}

}  // namespace

std::string overall_line(const StudySpec& spec, const StudyResult& result) {
  std::size_t reached = 0, finished = 0;
  std::string by_strategy;
  for (const std::string& strategy : spec.strategies) {
    std::size_t k = 0, n = 0;
    for (std::size_t w = 0; w < spec.worlds.size(); ++w) {
      for (const StudyRunResult* r : runs_of(spec, result, w, strategy)) {
        ++n;
        k += reached_goal(*r) ? 1 : 0;
      }
    }
    reached += k;
    finished += n;
    by_strategy += fmt::format("{}{} {}/{}", by_strategy.empty() ? "" : ", ", strategy, k, n);
  }
  std::string line = fmt::format("{} of {} missions reached the coverage goal of {:g} ({})", reached, finished,
                                 spec.mission.coverage_goal, by_strategy);
  const std::size_t missing = result.runs.size() - result.finished();
  if (missing > 0) line += fmt::format("; {} of {} planned missions are not finished", missing, result.runs.size());
  return line + ".";
}

StudyTable status_table(const StudySpec& spec, const StudyResult& result) {
  StudyTable t;
  t.header = {"strategy", "missions"};
  for (const char* s : kStatuses) t.header.emplace_back(s);
  std::vector<std::string> names = spec.strategies;
  names.emplace_back("all");
  for (const std::string& name : names) {
    std::map<std::string, std::size_t> counts;
    std::size_t n = 0;
    for (std::size_t w = 0; w < spec.worlds.size(); ++w) {
      for (const std::string& strategy : spec.strategies) {
        if (name != "all" && name != strategy) continue;
        for (const StudyRunResult* r : runs_of(spec, result, w, strategy)) {
          ++counts[r->summary.status];
          ++n;
        }
      }
    }
    std::vector<std::string> row = {name, std::to_string(n)};
    for (const char* s : kStatuses) row.push_back(std::to_string(counts[s]));
    t.rows.push_back(row);
  }
  return t;
}

StudyTable strategy_table(const StudySpec& spec, const StudyResult& result, std::size_t w) {
  StudyTable t;
  t.header = {"strategy",         "runs",        "reached 95 %",   "time to 95 % [s]",
              "path to 95 % [m]", "collisions",  "final coverage", "reachable area [m^2]",
              "share of plan",    "stuck goals", "backtracks",     "coverage with predictions"};
  for (const std::string& strategy : spec.strategies) {
    const auto runs = runs_of(spec, result, w, strategy);
    const auto [times, paths] = to_95(runs);
    int collisions = 0;
    std::vector<double> coverage, area, plan_share, stuck, backtracks, predicted;
    for (const StudyRunResult* r : runs) {
      collisions += r->summary.statistics.collisions;
      coverage.push_back(r->summary.coverage);
      area.push_back(r->summary.reachable_area_m2);
      if (r->plan_free_area_m2 > 0) plan_share.push_back(r->summary.reachable_area_m2 / r->plan_free_area_m2);
      stuck.push_back(r->summary.statistics.stuck_goals);
      backtracks.push_back(r->summary.statistics.backtracks);
      if (r->predicted_coverage >= 0) predicted.push_back(r->predicted_coverage);
    }
    t.rows.push_back({strategy, std::to_string(runs.size()), share(times.size(), runs.size()), mean_std(times, 1),
                      mean_std(paths, 1), std::to_string(collisions), mean_std(coverage, 3), mean_std(area, 1),
                      mean_std(plan_share, 3), mean_std(stuck, 1), mean_std(backtracks, 1),
                      predicted.empty() ? "-" : mean_std(predicted, 3)});
  }
  return t;
}

StudyTable welch_table(const StudySpec& spec, const StudyResult& result, std::size_t w) {
  StudyTable t;
  t.header = {"a", "b", "measure", "mean a - b", "t", "df", "p"};
  for (std::size_t i = 0; i < spec.strategies.size(); ++i) {
    for (std::size_t j = i + 1; j < spec.strategies.size(); ++j) {
      const std::string &a = spec.strategies[i], &b = spec.strategies[j];
      const auto [ta, pa] = to_95(runs_of(spec, result, w, a));
      const auto [tb, pb] = to_95(runs_of(spec, result, w, b));
      t.rows.push_back(test_row(a, b, "time to 95 % [s]", welch_t_test(ta, tb)));
      t.rows.push_back(test_row(a, b, "path to 95 % [m]", welch_t_test(pa, pb)));
    }
  }
  return t;
}

StudyTable paired_table(const StudySpec& spec, const StudyResult& result, std::size_t w) {
  StudyTable t;
  t.header = {"a", "b", "pairs", "a faster", "b faster", "mean a - b [s]", "t", "df", "p"};
  for (std::size_t i = 0; i < spec.strategies.size(); ++i) {
    for (std::size_t j = i + 1; j < spec.strategies.size(); ++j) {
      const std::string &a = spec.strategies[i], &b = spec.strategies[j];
      const auto ta = times_by_seed(spec, result, w, a), tb = times_by_seed(spec, result, w, b);
      std::vector<double> va, vb;
      int a_faster = 0, b_faster = 0;
      for (const auto& [seed, time] : ta) {
        const auto other = tb.find(seed);
        if (other == tb.end()) continue;
        va.push_back(time);
        vb.push_back(other->second);
        a_faster += time < other->second ? 1 : 0;
        b_faster += other->second < time ? 1 : 0;
      }
      const WelchResult r = paired_t_test(va, vb);
      std::vector<std::string> row = {a, b, std::to_string(va.size()), std::to_string(a_faster),
                                      std::to_string(b_faster)};
      if (r.defined) {
        for (const std::string& cell : {fmt::format("{:.2f}", r.mean_difference), fmt::format("{:.3f}", r.t),
                                        fmt::format("{:.0f}", r.df), fmt::format("{:.4f}", r.p)})
          row.push_back(cell);
      } else {
        row.insert(row.end(), {"n/a: " + r.why, "", "", ""});
      }
      t.rows.push_back(row);
    }
  }
  return t;
}

std::string to_markdown(const StudyTable& table) {
  std::string md = "|";
  for (const std::string& h : table.header) md += " " + h + " |";
  md += "\n|";
  for (std::size_t i = 0; i < table.header.size(); ++i) md += "---|";
  md += "\n";
  for (const auto& row : table.rows) {
    md += "|";
    for (const std::string& cell : row) md += " " + cell + " |";
    md += "\n";
  }
  return md;
}

}  // namespace lookahead::exploration
