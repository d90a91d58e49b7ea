// SPDX-License-Identifier: MIT
// Predictions on a worker thread, so the filter never waits for one (the paper ran its
// predictor in a thread of its own for the same reason, sec. V-B). The map is handed over
// as a copy: with copy-on-write tiles that costs microseconds and the filter goes on
// writing its own copy.
#pragma once

#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "lookahead/predictor/structure_predictor.hpp"

namespace lookahead::predictor {

class PredictionWorker {
 public:
  explicit PredictionWorker(const PredictorOptions& options);
  ~PredictionWorker();
  PredictionWorker(const PredictionWorker&) = delete;
  PredictionWorker& operator=(const PredictionWorker&) = delete;

  /// Queues a prediction of the region around (tx, ty); a queued request that has not
  /// started yet is replaced (only the latest target matters).
  void request(slam::OccupancyGrid map, double tx, double ty);
  /// The finished prediction, if one is ready (never blocks).
  std::optional<Prediction> poll();
  /// Blocks until the queued and running requests are done; their latest result, if any.
  /// A simulation uses it to deliver predictions at a fixed simulated latency, so that
  /// runs are reproducible whatever the machine's speed.
  std::optional<Prediction> wait();
  /// A request is queued or running.
  [[nodiscard]] bool busy() const;

 private:
  struct Request {
    slam::OccupancyGrid map;
    double x = 0, y = 0;
  };
  void loop();

  PredictorOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::optional<Request> queued_;
  std::optional<Prediction> result_;
  bool running_ = false, stop_ = false;
  std::thread thread_;
};

}  // namespace lookahead::predictor
