// An explicit, caller-owned cache of a solve's albedo-independent work: the interface operators
// (core/interfaces/layer_interfaces.h) and those of the interfaces between stacked layers
// (core/interfaces/internal_interface.h), reused by every re-solve that leaves the interfaces, the resolution and the
// outside directions alone, and the phase-function projections (core/medium/layer_phase.h), reused while g and the
// resolution stay. An Omega or T change then costs only the per-mode eigen-decomposition and boundary solve; a g change adds the
// phase projections; only sigma, eta or the bottom's interface rebuild the interface operators. Core keeps no hidden
// state: the cache is a value the caller owns and passes (SolveOptions::cache), bounded by a byte budget; the least
// recently used entries go first.
//
// Not thread-safe: one caller at a time (the solver looks entries up before it fans work out to
// SolveOptions::parallel_for).
#pragma once

#include <cstddef>
#include <list>
#include <memory>
#include <span>
#include <variant>
#include <vector>

#include "core/cancellation.h"
#include "core/interfaces/internal_interface.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/medium/layer_phase.h"

namespace skinlayer {

// What the interface operators depend on, exactly.
struct InterfaceKernelKey {
  LayerGeometry geometry;
  int ordinates = 0;
  int modes = 0;
  int azimuths = 0;
  std::vector<double> mu_in, mu_out;
  KernelSet set = KernelSet::All;

  bool operator==(const InterfaceKernelKey&) const = default;
};

// What the operators of an interface between stacked layers depend on, exactly.
struct InternalInterfaceKey {
  RoughDielectric interface;
  int ordinates = 0;
  int modes = 0;
  int azimuths = 0;
  std::vector<double> mu_in, mu_out;
  bool up_rows = false, down_rows = false, beam = false;  // InternalInterfaceNeeds
  bool operator==(const InternalInterfaceKey&) const = default;
};

// What the phase-function projections depend on, exactly.
struct PhaseKernelKey {
  double g = 0.0;
  int ordinates = 0;
  int modes = 0;
  int azimuths = 0;
  std::vector<double> mu_in, mu_out;
  bool beam = false;
  bool exterior = false;

  bool operator==(const PhaseKernelKey&) const = default;
};

class SolveCache {
 public:
  static constexpr std::size_t kDefaultBudgetBytes = std::size_t{64} << 20;
  explicit SolveCache(std::size_t budget_bytes = kDefaultBudgetBytes) : budget_bytes_(budget_bytes) {}

  // The cached value for `key`, or build() on a miss (kept unless it alone exceeds the budget).
  template <typename Build>
  std::shared_ptr<const InterfaceKernels> interface_kernels(const InterfaceKernelKey& key, Build&& build) {
    return find_or_build<InterfaceKernels>(key, build);
  }
  template <typename Build>
  std::shared_ptr<const PhaseKernels> phase_kernels(const PhaseKernelKey& key, Build&& build) {
    return find_or_build<PhaseKernels>(key, build);
  }
  template <typename Build>
  std::shared_ptr<const InternalInterfaceKernels> internal_interface_kernels(const InternalInterfaceKey& key,
                                                                             Build&& build) {
    return find_or_build<InternalInterfaceKernels>(key, build);
  }

  int hits() const { return hits_; }
  int misses() const { return misses_; }
  std::size_t entries() const { return entries_.size(); }
  std::size_t bytes() const { return bytes_; }

 private:
  using Key = std::variant<InterfaceKernelKey, PhaseKernelKey, InternalInterfaceKey>;
  struct Entry {
    Key key;
    std::shared_ptr<const void> value;
    std::size_t bytes;
  };

  template <typename Value, typename Build>
  std::shared_ptr<const Value> find_or_build(const Key& key, Build& build) {
    if (std::shared_ptr<const void> found = find(key)) return std::static_pointer_cast<const Value>(found);
    ++misses_;
    auto built = std::make_shared<const Value>(build());
    insert(key, built, built->bytes());
    return built;
  }
  std::shared_ptr<const void> find(const Key& key);
  void insert(const Key& key, std::shared_ptr<const void> value, std::size_t bytes);

  std::size_t budget_bytes_;
  std::size_t bytes_ = 0;
  std::list<Entry> entries_;  // most recently used first
  int hits_ = 0;
  int misses_ = 0;
};

// The phase-function projections of g at this resolution, from the cache where it has them (cache null: built for
// this call). The key names the outside directions only where the projections use them (beam: the open top's beam
// from mu_in; exterior: exits scattered to directly along mu_out), so that a solve without them finds the node
// matrices of another one.
// A build cancelled part-way (core/cancellation.h) throws before anything is cached.
std::shared_ptr<const PhaseKernels> cached_phase_kernels(SolveCache* cache, double g, const QuadratureRule& quadrature,
                                                         int modes, int azimuths, std::span<const double> mu_in,
                                                         std::span<const double> mu_out, bool beam, bool exterior,
                                                         const CancelCheck& cancelled = {});

}  // namespace skinlayer
