// SPDX-License-Identifier: MIT
// TUM trajectories: round trip, the parser under random and mutated input (it returns poses
// or throws ParseError naming the line, nothing else), and the ATE against a brute-force
// alignment on a known trajectory pair.
#include "lookahead/slam/io/tum_trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "lookahead/slam/eval/absolute_error.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::slam {
namespace {

using test::TempPath;

std::vector<StampedPose> random_walk(std::mt19937& rng, int n) {
  std::normal_distribution<double> step(0.0, 0.3);
  std::vector<StampedPose> poses;
  Pose2 p;
  for (int i = 0; i < n; ++i) {
    poses.push_back({1000.0 + 0.2 * i, p});
    p = p.compose({std::abs(step(rng)), 0.1 * step(rng), step(rng)});
  }
  return poses;
}

TEST(TumTrajectory, RoundTripsRandomTrajectories) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const auto poses = random_walk(rng, 50);
    TempPath path(".tum");
    write_tum_trajectory(path.str(), poses);
    ASSERT_TRUE(is_tum_trajectory(path.str()));
    const auto back = read_any_trajectory(path.str());
    ASSERT_EQ(back.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
      EXPECT_NEAR(back[i].t, poses[i].t, 1e-6);
      EXPECT_NEAR(back[i].pose.x, poses[i].pose.x, 1e-6);
      EXPECT_NEAR(back[i].pose.y, poses[i].pose.y, 1e-6);
      EXPECT_NEAR(normalize_angle(back[i].pose.theta - poses[i].pose.theta), 0.0, 1e-8);
    }
  }
}

TEST(TumTrajectory, ReadsEvoStyleFilesAndKeepsTheYaw) {
  TempPath path(".tum");
  // A 3D file: yaw 90 deg about z, then a pose rolled 180 deg about x (yaw of R stays 0).
  path.write(
      "# written by evo\n1.0 1 2 0.5 0 0 0.7071067811865476 0.7071067811865476\r\n"
      "2.0 3 4 0 1 0 0 0\n\n");
  const auto poses = read_tum_trajectory(path.str());
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_NEAR(poses[0].pose.theta, M_PI / 2, 1e-12);
  EXPECT_NEAR(poses[1].pose.theta, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(poses[1].pose.x, 3.0);
}

TEST(TumTrajectory, BadLinesNameFileLineFieldAndValue) {
  const std::pair<const char*, const char*> cases[] = {
      {"1 2 3 4 5 6 7\n", "fields"},
      {"1 2 3 4 0 0 0 1\n1 2 x 4 0 0 0 1\n", "ty"},
      {"1 2 3 4 0 0 0 0\n", "quaternion"},
      {"1 2 3 4 0 0 0 nan\n", "qw"},
  };
  for (const auto& [text, field] : cases) {
    TempPath path(".tum");
    path.write(text);
    try {
      read_tum_trajectory(path.str());
      ADD_FAILURE() << "accepted: " << text;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_EQ(e.file(), path.str());
      EXPECT_GE(e.line(), 1u);
    }
  }
}

// Property: on any mutation of a valid file the parser returns poses with finite fields or
// throws ParseError; nothing else escapes and nothing non-finite is returned.
TEST(TumTrajectory, FuzzedInputParsesOrThrowsParseError) {
  std::mt19937 rng(12345);
  const std::string alphabet = "0123456789.-+e #\t\nnaifx";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::mt19937 walk_rng(3);
  TempPath seed_file(".tum");
  write_tum_trajectory(seed_file.str(), random_walk(walk_rng, 6));
  std::ifstream in(seed_file.str());
  const std::string valid((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int parsed = 0, rejected = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(rng() % 6);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0:
          text[at] = alphabet[pick(rng)];
          break;
        case 1:
          text.insert(at, 1, alphabet[pick(rng)]);
          break;
        default:
          text.erase(at, 1 + rng() % 8);
          break;
      }
      if (text.empty()) text = "#";
    }
    TempPath path(".tum");
    path.write(text);
    try {
      for (const StampedPose& p : read_tum_trajectory(path.str())) {
        ASSERT_TRUE(std::isfinite(p.t) && std::isfinite(p.pose.x) && std::isfinite(p.pose.y) &&
                    std::isfinite(p.pose.theta))
            << text;
      }
      ++parsed;
    } catch (const ParseError&) {
      ++rejected;
    }
  }
  EXPECT_GT(parsed, 0);    // some mutations stay valid (digits for digits) ...
  EXPECT_GT(rejected, 0);  // ... and many do not
}

// Direct computation: the RMSE after the best rigid alignment, found by scanning the angle
// (the best translation for a fixed angle is the difference of the centroids).
double brute_force_ate(const std::vector<StampedPose>& ref, const std::vector<StampedPose>& est) {
  const double n = static_cast<double>(ref.size());
  double best = 1e300;
  for (int k = 0; k < 200000; ++k) {
    const double th = -M_PI + 2 * M_PI * k / 200000.0;
    const double c = std::cos(th), s = std::sin(th);
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      mx += (ref[i].pose.x - (c * est[i].pose.x - s * est[i].pose.y)) / n;
      my += (ref[i].pose.y - (s * est[i].pose.x + c * est[i].pose.y)) / n;
    }
    double sq = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      const double dx = c * est[i].pose.x - s * est[i].pose.y + mx - ref[i].pose.x;
      const double dy = s * est[i].pose.x + c * est[i].pose.y + my - ref[i].pose.y;
      sq += dx * dx + dy * dy;
    }
    best = std::min(best, std::sqrt(sq / n));
  }
  return best;
}

TEST(TumTrajectory, AteThroughTumFilesMatchesABruteForceAlignment) {
  std::mt19937 rng(99);
  const auto reference = random_walk(rng, 40);
  // The estimate: the reference in another frame (rotated 0.7 rad, shifted) plus known errors.
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<StampedPose> estimate;
  const Pose2 frame{3.0, -2.0, 0.7};
  for (const auto& r : reference) {
    const Pose2 p = frame.compose(r.pose);
    estimate.push_back({r.t, {p.x + noise(rng), p.y + noise(rng), p.theta}});
  }
  TempPath ref_file(".tum"), est_file(".tum");
  write_tum_trajectory(ref_file.str(), reference);
  write_tum_trajectory(est_file.str(), estimate);
  const auto ref = read_any_trajectory(ref_file.str());
  const auto est = read_any_trajectory(est_file.str());
  const AbsoluteError ate = absolute_trajectory_error(ref, est, 1e-4);
  EXPECT_EQ(ate.matched, reference.size());
  EXPECT_GT(ate.rmse, 0.02);
  EXPECT_NEAR(ate.rmse, brute_force_ate(ref, est), 1e-6);
  EXPECT_NEAR(normalize_angle(ate.alignment.theta + 0.7), 0.0, 0.05);
}

}  // namespace
}  // namespace lookahead::slam
