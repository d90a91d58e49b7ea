// SPDX-License-Identifier: MIT
#include "lookahead/predictor/prediction_worker.hpp"

namespace lookahead::predictor {

PredictionWorker::PredictionWorker(const PredictorOptions& options)
    : options_((validate(options), options)), thread_([this] { loop(); }) {}

PredictionWorker::~PredictionWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void PredictionWorker::request(slam::OccupancyGrid map, double tx, double ty) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queued_ = Request{std::move(map), tx, ty};
  }
  wake_.notify_one();
}

std::optional<Prediction> PredictionWorker::poll() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<Prediction> out = std::move(result_);
  result_.reset();
  return out;
}

std::optional<Prediction> PredictionWorker::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return !queued_ && !running_; });
  std::optional<Prediction> out = std::move(result_);
  result_.reset();
  return out;
}

bool PredictionWorker::busy() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return queued_.has_value() || running_;
}

void PredictionWorker::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || queued_.has_value(); });
    if (stop_) return;
    Request r = std::move(*queued_);
    queued_.reset();
    running_ = true;
    lock.unlock();
    Prediction p = predict_structure(r.map, r.x, r.y, options_);
    lock.lock();
    result_ = std::move(p);
    running_ = false;
    if (!queued_) done_.notify_all();
  }
}

}  // namespace lookahead::predictor
