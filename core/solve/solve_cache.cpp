#include "core/solve/solve_cache.h"

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

std::shared_ptr<const PhaseKernels> cached_phase_kernels(SolveCache* cache, double g, const QuadratureRule& quadrature,
                                                         int modes, int azimuths, std::span<const double> mu_in,
                                                         std::span<const double> mu_out, bool beam, bool exterior,
                                                         const CancelCheck& cancelled) {
  const PhaseKernelKey key{g,
                           static_cast<int>(quadrature.size()),
                           modes,
                           azimuths,
                           beam ? std::vector<double>(mu_in.begin(), mu_in.end()) : std::vector<double>{},
                           exterior ? std::vector<double>(mu_out.begin(), mu_out.end()) : std::vector<double>{},
                           beam,
                           exterior};
  const auto build = [&] {
    return phase_kernels(key.g, quadrature, key.modes, key.azimuths, key.mu_in, key.mu_out, key.beam, key.exterior,
                         cancelled);
  };
  return cache ? cache->phase_kernels(key, build) : std::make_shared<const PhaseKernels>(build());
}

}  // namespace skinlayer
