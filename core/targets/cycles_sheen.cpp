// docs/model.md §22.1.1: Cycles' sheen, Zeltner et al. 2022's LTC read from Cycles' table.
#include "core/targets/cycles_sheen.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/targets/cycles_lookup_table.h"
#include "core/targets/zeltner_fuzz.h"

namespace skinlayer {
namespace {

constexpr int kNodes = 32;
constexpr std::size_t kValues = 3 * kNodes * kNodes;

// a, b and E, each kNodes x kNodes, the view's cosine running fastest.
constexpr std::array<double, kValues> kSheenLtc = {
#include "core/targets/cycles_sheen_ltc_table.inc"
};

CyclesLookupTable block(int k) {
  return CyclesLookupTable(kNodes, kNodes, 1, [k](int x, int y, int) {
    return kSheenLtc[static_cast<std::size_t>(k * kNodes * kNodes + y * kNodes + x)];
  });
}

struct SheenTables {
  CyclesLookupTable a = block(0), b = block(1), albedo = block(2);
};

const SheenTables& tables() {
  static const SheenTables instance;  // immutable once built
  return instance;
}

struct SheenSetup {
  double a = 0.0, b = 0.0, albedo = 0.0;
  bool made = false;
};

// bsdf_sheen_setup: the view's cosine and the clamped roughness pick the LTC and the albedo.
SheenSetup setup(double mu_o, double roughness) {
  const double r = std::clamp(roughness, 1e-3, 1.0);
  const SheenTables& t = tables();
  SheenSetup s{t.a.read(mu_o, r), t.b.read(mu_o, r), t.albedo.read(mu_o, r)};
  s.made = std::abs(s.a) >= 1e-5 && s.albedo >= 1e-5;
  return s;
}

}  // namespace

double cycles_sheen_albedo(double mu_o, double roughness) {
  const SheenSetup s = setup(mu_o, roughness);
  return s.made ? s.albedo : 0.0;
}

double cycles_sheen_cosine_weighted(double roughness, const Vec3& omega_i, const Vec3& omega_o) {
  if (!(omega_i.z() > 0.0 && omega_o.z() > 0.0)) return 0.0;
  const SheenSetup s = setup(omega_o.z(), roughness);
  if (!s.made) return 0.0;
  return s.albedo * zeltner_ltc_distribution(s.a, s.b, omega_i, omega_o);
}

}  // namespace skinlayer
