// The previewer's translucency (app/solution/sphere_spread.h): the shown material's profile, computed on a thread of
// its own after its BRDF is on screen, so that the window keeps drawing and the slider-to-frame path is untouched.
// One at a time: a material that changes while one runs waits for it, and the stale outcome is dropped by the
// caller (its document says which material it answers). The thread is joined by the destructor (RAII).
#pragma once

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "app/material/material_document.h"
#include "app/solution/sphere_spread.h"

namespace skinlayer {

struct SpreadOutcome {
  MaterialDocument document;             // the material it answers
  std::optional<SpreadProfile> profile;  // unset: the material has none yet (why says so)
  std::string why;                       // the one line of a material without a profile
};

class SpreadJob {
 public:
  SpreadJob() = default;
  SpreadJob(const SpreadJob&) = delete;
  SpreadJob& operator=(const SpreadJob&) = delete;
  ~SpreadJob();

  // Starts the profile of `document` (a skin on its preview wavelengths). Returns false, and starts nothing, while
  // another runs.
  bool start(MaterialDocument document);
  bool running() const { return running_.load(); }
  // The outcome of a profile that has ended since the last call, once.
  std::optional<SpreadOutcome> take_outcome();

 private:
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::mutex mutex_;  // guards outcome_
  std::optional<SpreadOutcome> outcome_;
};

}  // namespace skinlayer
