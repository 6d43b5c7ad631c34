// The previewer's translucency (app/solution/sphere_spread.h): the shown material's profile, computed on a thread of
// its own after its BRDF is on screen, so that the window keeps drawing and the slider-to-frame path is untouched.
// One at a time: a material that changes while one runs waits for it, and the stale outcome is dropped by the
// caller (its document says which material it answers). The thread is one_shot_job.h's.
#pragma once

#include <optional>
#include <string>

#include "app/material/material_document.h"
#include "app/solution/sphere_spread.h"
#include "app/window/one_shot_job.h"

namespace skinlayer {

struct SpreadOutcome {
  MaterialDocument document;             // the material it answers
  std::optional<SpreadProfile> profile;  // unset: the material has none yet (why says so)
  std::string why;                       // the one line of a material without a profile
};

class SpreadJob {
 public:
  // Starts the profile of `document` (a skin on its preview wavelengths). Returns false, and starts nothing, while
  // another runs.
  bool start(MaterialDocument document);
  bool running() const { return job_.running(); }
  // The outcome of a profile that has ended since the last call, once.
  std::optional<SpreadOutcome> take_outcome() { return job_.take_outcome(); }

 private:
  OneShotJob<SpreadOutcome> job_;
};

}  // namespace skinlayer
