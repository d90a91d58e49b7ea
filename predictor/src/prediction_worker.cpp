// SPDX-License-Identifier: MIT
#include "lookahead/predictor/prediction_worker.hpp"

#include <chrono>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace lookahead::predictor {
namespace {

// Linux applies setpriority() to a single thread when given its thread id (not POSIX:
// elsewhere the worker keeps the process's priority).
void lower_this_thread_priority() {
#ifdef __linux__
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
}

}  // namespace

PredictionWorker::PredictionWorker(const PredictorOptions& options, Priority priority)
    : priority_(priority), options_((validate(options), options)), thread_([this] { loop(); }) {}

PredictionWorker::~PredictionWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void PredictionWorker::request(slam::OccupancyGrid map, double tx, double ty) {
  request(std::move(map), std::vector<std::pair<double, double>>{{tx, ty}});
}

void PredictionWorker::request(slam::OccupancyGrid map, std::vector<std::pair<double, double>> candidates) {
  if (candidates.empty()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queued_ = Request{std::move(map), std::move(candidates)};
  }
  wake_.notify_one();
}

// Copy-on-write: a map whose tiles all are the modelled map's tiles has the same cells.
const ExploredMapModel& PredictionWorker::model_of(const slam::OccupancyGrid& map) {
  const std::size_t tiles = map.tile_count();
  const bool same =
      modelled_map_ && model_ && modelled_map_->tile_count() == tiles && modelled_map_->tiles_shared_with(map) == tiles;
  if (!same) {
    model_ = model_explored_map(map, options_);
    modelled_map_ = map;
    ++maps_modelled_;
  }
  return *model_;
}

Prediction PredictionWorker::run(const Request& r) {
  const auto t0 = std::chrono::steady_clock::now();
  const ExploredMapModel& model = model_of(r.map);
  Prediction p;
  for (const auto& [x, y] : r.targets) {
    p = predict_structure(r.map, model, x, y, options_);
    if (p.status != Prediction::Status::kNoControlPoint) break;
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

std::optional<Prediction> PredictionWorker::take_result() {
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  std::optional<Prediction> out = std::move(result_);
  result_.reset();
  return out;
}

std::optional<Prediction> PredictionWorker::poll() {
  std::lock_guard<std::mutex> lock(mutex_);
  return take_result();
}

std::optional<Prediction> PredictionWorker::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return !queued_ && !running_; });
  return take_result();
}

bool PredictionWorker::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return queued_.has_value() || running_;
}

void PredictionWorker::loop() {
  if (priority_ == Priority::kBackground) lower_this_thread_priority();
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || queued_.has_value(); });
    if (stop_) return;
    Request r = std::move(*queued_);
    queued_.reset();
    running_ = true;
    lock.unlock();
    std::optional<Prediction> p;
    std::exception_ptr error;
    try {
      p = run(r);
    } catch (...) {
      error = std::current_exception();  // would call std::terminate on this thread
    }
    lock.lock();
    result_ = std::move(p);
    if (error && !error_) error_ = error;
    running_ = false;
    if (!queued_) done_.notify_all();
  }
}

}  // namespace lookahead::predictor
