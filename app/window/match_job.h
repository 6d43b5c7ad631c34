// The previewer's "Match colour..." (app/material/color_match.h: 0.2-1.4 s on 2 cores), on a thread of its own so
// that the window keeps drawing (one_shot_job.h: one at a time, its outcome taken once when it ends).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "app/material/material_document.h"
#include "app/window/one_shot_job.h"

namespace skinlayer {

struct MatchOutcome {
  std::optional<MaterialDocument> document;  // the matched material; unset when the match failed
  std::string line;                          // "matched ... (CIEDE2000 0.02)", "out of reach: ...", or the error
};

class MatchJob {
 public:
  // Starts matching `document` to the sRGB-encoded colour `srgb`. Returns false, and starts nothing, while another
  // match runs.
  bool start(MaterialDocument document, const Eigen::Vector3d& srgb);

  bool running() const { return job_.running(); }
  // The outcome of a match that has ended since the last call, once.
  std::optional<MatchOutcome> take_outcome() { return job_.take_outcome(); }

 private:
  OneShotJob<MatchOutcome> job_;
};

}  // namespace skinlayer
