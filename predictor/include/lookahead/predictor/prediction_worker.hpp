// SPDX-License-Identifier: MIT
// Predictions on a worker thread, so the filter never waits for one (the paper ran its
// predictor in a thread of its own for the same reason, sec. V-B). The map is handed over
// as a copy: with copy-on-write tiles that costs microseconds and the filter goes on
// writing its own copy.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "lookahead/predictor/structure_predictor.hpp"

namespace lookahead::predictor {

class PredictionWorker {
 public:
  /// kBackground lowers the worker thread to the lowest CPU priority (nice 19, Linux): the
  /// filter's threads then take the cores first and the prediction uses what they leave,
  /// so it cannot slow the filter's update rate (P-SLAM runs prediction alongside the
  /// filter without holding it up). Callers that wait() for
  /// every prediction (reproducible missions) keep kNormal: waiting on a starved thread
  /// would cost them more than it saves.
  enum class Priority { kNormal, kBackground };
  explicit PredictionWorker(const PredictorOptions& options, Priority priority = Priority::kNormal);
  ~PredictionWorker();
  PredictionWorker(const PredictionWorker&) = delete;
  PredictionWorker& operator=(const PredictionWorker&) = delete;

  /// Queues a prediction of the region around (tx, ty); a queued request that has not
  /// started yet is replaced (only the latest target matters).
  void request(slam::OccupancyGrid map, double tx, double ty);
  /// The same for candidate targets in order of preference: the map is modelled once and
  /// the first candidate with a control point in range is predicted (a log has no
  /// exploration goal, so any frontier ahead that allows a prediction will do).
  void request(slam::OccupancyGrid map, std::vector<std::pair<double, double>> candidates);
  /// The finished prediction, if one is ready (never blocks). An exception the prediction
  /// threw on the worker thread is rethrown here (and by wait()), on the caller's thread.
  std::optional<Prediction> poll();
  /// Blocks until the queued and running requests are done; their latest result, if any.
  /// A simulation uses it to deliver predictions at a fixed simulated latency, so that
  /// runs are reproducible whatever the machine's speed.
  std::optional<Prediction> wait();
  /// A request is queued or running.
  [[nodiscard]] bool busy() const;
  /// Maps modelled so far (a request on the map of the previous one reuses its model).
  [[nodiscard]] int maps_modelled() const { return maps_modelled_.load(); }

 private:
  struct Request {
    slam::OccupancyGrid map;
    std::vector<std::pair<double, double>> targets;
  };
  Prediction run(const Request& r);
  std::optional<Prediction> take_result();  // with mutex_ held
  const ExploredMapModel& model_of(const slam::OccupancyGrid& map);
  void loop();
  Priority priority_;

  PredictorOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::optional<Request> queued_;
  std::optional<Prediction> result_;
  std::exception_ptr error_;  // thrown by run(), handed to the next poll() or wait()
  bool running_ = false, stop_ = false;
  // The last map modelled and its model, touched by the worker thread only: a mission
  // sends the targets of one selection one by one on the same map.
  std::optional<slam::OccupancyGrid> modelled_map_;
  std::optional<ExploredMapModel> model_;
  std::atomic<int> maps_modelled_{0};
  std::thread thread_;
};

}  // namespace lookahead::predictor
