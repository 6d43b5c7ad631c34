// The previewer's test hook, --test-actions (app/window/window_options.h): a script of actions that the window runs
// one a frame, once it is ready for the next, so that each edit is solved and committed as its own undo step, as a
// person's would be. A drag moves on one value every frame without waiting, as the mouse does, and commits once when
// it ends. The verbs are read here; the previewer carries them out through TestActionTarget, and the edits that
// change its state alone (set, layer, skin, lighting, split) are app/preview/scripted_edit.h's.
//   undo | redo | quit | discard      as the buttons and keys
//   drop PATH | save PATH | preset NAME   a file dropped on the window, Save as, a preset chosen
//   title                             prints the window's title
//   export-merl|export-bsdf|export-rgl [PATH]   the Export buttons
//   match R,G,B                       "Match colour..." with that sRGB-encoded colour
//   drag NAME V1,V2,...               a slider dragged through the values
//   rest                              waits for the window to rest (no solve, export or match in flight)
//   memory                            at rest, prints resident memory, heap in use and the solve cache
//   pin | unpin                       the A/B comparison's buttons
#pragma once

#include <array>
#include <chrono>
#include <deque>
#include <string>
#include <vector>

#include "app/preview/preview_state.h"
#include "app/solution/fitted_tables.h"
#include "app/window/export_job.h"
#include "app/window/file_panel.h"
#include "app/window/shortcuts.h"

namespace skinlayer {

// What a scripted action does at once to the previewer, which implements it.
class TestActionTarget {
 public:
  virtual PreviewState& state() = 0;  // what the scripted edits change
  virtual void print_title() = 0;
  virtual void start_export(ExportFormat format, const std::string& path) = 0;
  virtual void start_match(const std::array<double, 3>& srgb) = 0;
  virtual void print_memory() = 0;
  virtual void pin() = 0;
  virtual void pin_fit(ShaderTarget target) = 0;  // B: the shown material's fitted shader
  virtual void unpin() = 0;

 protected:
  ~TestActionTarget() = default;
};

// Whether the window may take the next action this frame.
struct TestActionReadiness {
  bool settled = false;  // a result is shown and answers the current parameters; no match runs
  bool resting = false;  // the window has come to rest (no solve, export or match in flight)
  FileDialog::Kind dialog = FileDialog::Kind::None;
};

class TestActionScript {
 public:
  explicit TestActionScript(const std::vector<std::string>& actions);

  // Runs this frame's step: the next value of a drag, or the next action once `ready` allows it. What the frame
  // itself carries out (undo, redo, quit and the file commands) goes into `requests`; the rest goes to `target`.
  // Throws std::runtime_error ("test action: ...") for an unknown or malformed action.
  void step(const TestActionReadiness& ready, TestActionTarget& target, ActionRequests& requests);

  bool finished() const { return actions_.empty() && drag_steps_.empty(); }
  bool dragging() const { return !drag_steps_.empty(); }
  // When the last action ran (or the script began): a capture waits for the final solve counted from it.
  std::chrono::steady_clock::time_point last_action() const { return last_action_; }

 private:
  std::deque<std::string> actions_;
  std::deque<std::string> drag_steps_;  // a drag's "set" edits still to make, one a frame
  std::chrono::steady_clock::time_point last_action_ = std::chrono::steady_clock::now();
};

}  // namespace skinlayer
