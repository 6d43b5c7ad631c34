// Undo and redo for the previewer: a bounded history of what the user edits (the material and the light), as
// plain values the previewer owns. One slider drag, or one drag of the light, is one step: a change is committed
// when the editing gesture ends.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "app/preview/preview_state.h"

namespace skinlayer {

struct Edit {
  ColorMaterial material;
  LightState light;
};

// Every field of the material (layer.albedo excepted: albedo_rgb is used), the model and the light.
bool same_edit(const Edit& a, const Edit& b);

class EditHistory {
 public:
  static constexpr std::size_t kDefaultLimit = 200;  // steps kept; the oldest go first

  explicit EditHistory(Edit initial, std::size_t limit = kDefaultLimit);

  // Called once a frame with what is on the controls. While `editing` (a control or the light is being dragged) a
  // change waits; once editing stops, a change since the last commit becomes one undo step and clears redo.
  void observe(const Edit& current, bool editing);

  // The edit to show after undoing or redoing one step, or nullopt when there is none. A change not yet committed
  // is committed first, so undo never loses it silently.
  std::optional<Edit> undo(const Edit& current);
  std::optional<Edit> redo(const Edit& current);

  std::size_t undo_steps() const { return past_.size(); }
  std::size_t redo_steps() const { return future_.size(); }

 private:
  void commit(const Edit& current);

  std::vector<Edit> past_;    // oldest first
  std::vector<Edit> future_;  // the next redo last
  Edit committed_;
  std::size_t limit_;
};

}  // namespace skinlayer
