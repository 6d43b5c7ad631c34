#include "app/window/spread_job.h"

#include <exception>
#include <utility>

#include "app/process/parallel_for.h"

namespace skinlayer {

bool SpreadJob::start(MaterialDocument document) {
  return job_.start([document = std::move(document)] {
    SpreadOutcome outcome{document, std::nullopt, {}};
    try {
      outcome.profile = spread_profile(document, true, parallel_for_threads);
    } catch (const std::exception& error) {
      outcome.why = error.what();
    }
    return outcome;
  });
}

}  // namespace skinlayer
