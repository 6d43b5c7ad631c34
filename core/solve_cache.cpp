#include "core/solve_cache.h"

namespace skinlayer {

std::shared_ptr<const void> SolveCache::find(const Key& key) {
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    if (it->key == key) {
      entries_.splice(entries_.begin(), entries_, it);
      ++hits_;
      return entries_.front().value;
    }
  }
  return nullptr;
}

void SolveCache::insert(const Key& key, std::shared_ptr<const void> value, std::size_t bytes) {
  if (bytes > budget_bytes_) return;
  entries_.push_front({key, std::move(value), bytes});
  bytes_ += bytes;
  while (bytes_ > budget_bytes_) {
    bytes_ -= entries_.back().bytes;
    entries_.pop_back();
  }
}

}  // namespace skinlayer
