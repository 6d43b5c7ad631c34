#include "app/preview/edit_history.h"

#include <utility>

#include "app/preview/solve_request.h"

namespace skinlayer {

bool same_edit(const Edit& a, const Edit& b) {
  return same_request(SolveRequest{a.material}, SolveRequest{b.material}) &&
         a.light.theta_degrees == b.light.theta_degrees && a.light.phi_degrees == b.light.phi_degrees;
}

EditHistory::EditHistory(Edit initial, std::size_t limit) : committed_(std::move(initial)), limit_(limit) {}

void EditHistory::commit(const Edit& current) {
  if (same_edit(current, committed_)) return;
  past_.push_back(committed_);
  if (past_.size() > limit_) past_.erase(past_.begin());
  future_.clear();
  committed_ = current;
}

void EditHistory::observe(const Edit& current, bool editing) {
  if (!editing) commit(current);
}

std::optional<Edit> EditHistory::undo(const Edit& current) {
  commit(current);
  if (past_.empty()) return std::nullopt;
  future_.push_back(committed_);
  committed_ = past_.back();
  past_.pop_back();
  return committed_;
}

std::optional<Edit> EditHistory::redo(const Edit& current) {
  commit(current);
  if (future_.empty()) return std::nullopt;
  past_.push_back(committed_);
  committed_ = future_.back();
  future_.pop_back();
  return committed_;
}

}  // namespace skinlayer
