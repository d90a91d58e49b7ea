// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf3d/rbpf3d.hpp"

#include <omp.h>

#include <chrono>
#include <stdexcept>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "lookahead/slam/rbpf3d/motion3_model.hpp"

namespace lookahead::slam {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Trajectory3Node::~Trajectory3Node() {
  std::shared_ptr<const Trajectory3Node> next = std::move(parent);
  while (next && next.use_count() == 1) {
    // Steal the parent's link before `next` dies, so its destructor finds nothing to free.
    std::shared_ptr<const Trajectory3Node> up = std::move(const_cast<Trajectory3Node&>(*next).parent);
    next = std::move(up);
  }
}

void Rbpf3dOptions::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("rbpf3d: ") + what);
  };
  require(particles >= 1 && particles <= 100000, "particles must be in 1..100000");
  require(threads >= 0, "threads must be >= 0");
  require(resample_threshold > 0.0 && resample_threshold <= 1.0, "resample_threshold must be in (0, 1]");
  require(weight_exponent > 0.0, "weight_exponent must be > 0");
  require(likelihood_ray_step >= 1 && insert_ray_step >= 1, "ray steps must be >= 1");
  require(insert.max_range > 0.0, "insert max_range must be > 0");
  require(motion.xy_per_metre >= 0 && motion.z_per_metre >= 0 && motion.yaw_per_metre >= 0 &&
              motion.yaw_per_radian >= 0 && motion.min_xy >= 0 && motion.min_yaw >= 0,
          "motion noise must be >= 0");
  map.validate();
  likelihood.validate();
}

Rbpf3d::Rbpf3d(const Rbpf3dOptions& options) : options_(options), rng_(options.seed) { options_.validate(); }

int Rbpf3d::thread_count() const { return options_.threads > 0 ? options_.threads : omp_get_num_procs(); }

void Rbpf3d::add_sweep(const RangeSweep& sweep) {
  if (particles_.empty()) {
    // Every particle starts at the first odometry pose with the same (shared) map.
    Particle3 first{sweep.odometry, EvidenceOctree(options_.map), 0.0, nullptr};
    particles_.assign(static_cast<std::size_t>(options_.particles), first);
  } else {
    predict_and_weigh(sweep);
    resample_if_needed();
  }
  insert(sweep);
  last_odometry_ = sweep.odometry;
  ++stats_.sweeps;
}

void Rbpf3d::predict_and_weigh(const RangeSweep& sweep) {
  const auto start = std::chrono::steady_clock::now();
  const Pose3 increment = last_odometry_.inverse() * sweep.odometry;
  const Euler imu = euler_of(sweep.odometry.linear());
  const double yaw_change = normalize_angle(imu.yaw - euler_of(last_odometry_.linear()).yaw);
  std::vector<Eigen::Vector3d> ends;  // robot frame; every n-th beam that hit
  for (std::size_t i = 0, hits = 0; i < sweep.rays.size(); ++i) {
    if (sweep.rays[i].hit && hits++ % static_cast<std::size_t>(options_.likelihood_ray_step) == 0) {
      ends.push_back(sweep.rays[i].end);
    }
  }
  std::vector<std::uint64_t> seeds(particles_.size());
  for (auto& s : seeds) s = rng_();  // drawn in order: same result on any thread count
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(thread_count())
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) {
    errors.run([&] {
      Particle3& p = particles_[static_cast<std::size_t>(i)];
      std::mt19937_64 rng(seeds[static_cast<std::size_t>(i)]);
      p.pose = sample_motion3(p.pose, increment, imu, yaw_change, options_.motion, rng);
      std::vector<Eigen::Vector3d> world(ends.size());
      for (std::size_t k = 0; k < ends.size(); ++k) world[k] = p.pose * ends[k];
      p.log_weight += options_.weight_exponent * octree_log_likelihood(p.map, world, options_.likelihood);
    });
  }
  errors.rethrow();
  stats_.predict_weight_seconds += seconds_since(start);
}

// Selective resampling (Grisetti et al. 2007, sec. IV step 5), as SegSLAM sec. 2.2 uses it.
void Rbpf3d::resample_if_needed() {
  bool resampled = false;
  stats_.neff.push_back(resample_if_degenerate(particles_, options_.resample_threshold, rng_, resampled));
  if (resampled) ++stats_.resamplings;
}

void Rbpf3d::insert(const RangeSweep& sweep) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Ray3> local;
  for (std::size_t i = 0; i < sweep.rays.size(); i += static_cast<std::size_t>(options_.insert_ray_step)) {
    local.push_back(sweep.rays[i]);
  }
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(thread_count())
  for (int i = 0; i < static_cast<int>(particles_.size()); ++i) {
    errors.run([&] {
      Particle3& p = particles_[static_cast<std::size_t>(i)];
      std::vector<Ray3> rays(local.size());
      for (std::size_t k = 0; k < local.size(); ++k) {
        rays[k] = {p.pose * local[k].origin, p.pose * local[k].end, local[k].hit};
      }
      insert_rays(p.map, rays, options_.insert);
      p.trajectory = std::make_shared<const Trajectory3Node>(p.pose, p.trajectory);
    });
  }
  errors.rethrow();
  stats_.insert_seconds += seconds_since(start);
}

std::size_t Rbpf3d::best_particle() const { return best_particle_index(particles_); }

Eigen::Vector3d Rbpf3d::mean_position() const {
  return weighted_mean_position(particle_weights(particles_),
                                [&](std::size_t i) -> Eigen::Vector3d { return particles_[i].pose.translation(); });
}

std::vector<Pose3> Rbpf3d::trajectory(std::size_t particle) const {
  std::vector<Pose3> poses;
  for (const Trajectory3Node* n : chain_oldest_first(particles_.at(particle).trajectory.get()))
    poses.push_back(n->pose);
  return poses;
}

}  // namespace lookahead::slam
