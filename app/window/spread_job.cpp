#include "app/window/spread_job.h"

#include <exception>
#include <utility>

#include "app/process/parallel_for.h"

namespace skinlayer {

SpreadJob::~SpreadJob() {
  if (thread_.joinable()) thread_.join();
}

bool SpreadJob::start(MaterialDocument document) {
  if (running_.load()) return false;
  if (thread_.joinable()) thread_.join();
  running_ = true;
  thread_ = std::thread([this, document = std::move(document)] {
    SpreadOutcome outcome{document, std::nullopt, {}};
    try {
      outcome.profile = spread_profile(document, true, parallel_for_threads);
    } catch (const std::exception& error) {
      outcome.why = error.what();
    }
    {
      const std::lock_guard lock(mutex_);
      outcome_ = std::move(outcome);
    }
    running_ = false;
  });
  return true;
}

std::optional<SpreadOutcome> SpreadJob::take_outcome() {
  const std::lock_guard lock(mutex_);
  return std::exchange(outcome_, std::nullopt);
}

}  // namespace skinlayer
