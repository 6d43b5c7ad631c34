// A piece of the previewer's work on a thread of its own, one at a time, whose outcome is taken once when it ends:
// what "Match colour..." (match_job.h) and the translucency's profile (spread_job.h) share. The thread is joined by
// the destructor (RAII); the work cannot be cancelled (it changes nothing until its outcome is taken).
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace skinlayer {

template <class Outcome>
class OneShotJob {
 public:
  OneShotJob() = default;
  OneShotJob(const OneShotJob&) = delete;
  OneShotJob& operator=(const OneShotJob&) = delete;
  ~OneShotJob() {
    if (thread_.joinable()) thread_.join();
  }

  // Runs `work` on the job's thread. Returns false, and starts nothing, while another runs. `work` must not throw:
  // its failures are part of its outcome.
  bool start(std::function<Outcome()> work) {
    if (running_.load()) return false;
    if (thread_.joinable()) thread_.join();
    running_ = true;
    thread_ = std::thread([this, work = std::move(work)] {
      Outcome outcome = work();
      {
        const std::lock_guard lock(mutex_);
        outcome_ = std::move(outcome);
      }
      running_ = false;
    });
    return true;
  }

  bool running() const { return running_.load(); }
  // The outcome of work that has ended since the last call, once.
  std::optional<Outcome> take_outcome() {
    const std::lock_guard lock(mutex_);
    return std::exchange(outcome_, std::nullopt);
  }

 private:
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::mutex mutex_;  // guards outcome_
  std::optional<Outcome> outcome_;
};

}  // namespace skinlayer
