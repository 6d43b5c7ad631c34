// The previewer's "Match colour..." (app/material/color_match.h: 0.2-1.4 s on 2 cores), on a thread of its own so
// that the window keeps drawing: one at a time, its outcome taken once when it ends. The thread is joined by the
// destructor (RAII); a match cannot be cancelled (it changes nothing until its outcome is taken).
#pragma once

#include <Eigen/Core>
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/material/material_document.h"

namespace skinlayer {

struct MatchOutcome {
  std::optional<MaterialDocument> document;  // the matched material; unset when the match failed
  std::string line;                          // "matched ... (CIEDE2000 0.02)", "out of reach: ...", or the error
};

class MatchJob {
 public:
  MatchJob() = default;
  MatchJob(const MatchJob&) = delete;
  MatchJob& operator=(const MatchJob&) = delete;
  ~MatchJob();

  // Starts matching `document` to the sRGB-encoded colour `srgb`. Returns false, and starts nothing, while another
  // match runs.
  bool start(MaterialDocument document, const Eigen::Vector3d& srgb);

  bool running() const { return running_.load(); }
  // The outcome of a match that has ended since the last call, once.
  std::optional<MatchOutcome> take_outcome();

 private:
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::mutex mutex_;  // guards outcome_
  std::optional<MatchOutcome> outcome_;
};

}  // namespace skinlayer
