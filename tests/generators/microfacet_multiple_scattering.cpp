// The generator of core/data/microfacet_multiple_scattering.csv: what a rough dielectric interface scatters more
// than once on its microsurface, from the microsurface random walk (core/reference/microsurface_walk.h), tabulated
// for core/interfaces/multiple_scattering.h.
//
// For each Beckmann sigma, relative index e = n_other / n_incident (light arriving from the side of index 1, e the
// index beyond) and incident polar angle of the grids below, `kWalks` walks; those that met the microsurface more
// than once are tallied by exit side and exit polar angle in kExitBins bins 5 degrees wide, whose centres are the
// incident angles (so that the table's two directions share one grid). Each bin's value is the azimuthally averaged
// BSDF of the multiply scattered light there, f = (walks in the bin / walks) / (pi (cos^2 lo - cos^2 hi)), in 1/sr:
// reflection (back to the incident side) and transmission (beyond) in columns r0.. and t0...
//
//   cmake --build build --target microfacet-tables      (about 4 minutes on 2 cores)
//
// writes the CSV in the source tree. The walks are seeded per row (from its indices), so the table is the same on
// every run with the same thread count or any other.
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/conventions.h"
#include "core/reference/microsurface_walk.h"

namespace skinlayer {
namespace {

constexpr std::array<double, 13> kSigmas = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
// Relative indices from the incident side: interfaces of eta in (1, 2.5] seen from above and from below.
constexpr std::array<double, 21> kIndices = {0.4,  0.45, 0.5, 0.56, 0.63, 0.7, 0.77, 0.83, 0.9, 0.95, 1.0,
                                             1.05, 1.1,  1.2, 1.3,  1.43, 1.6, 1.8,  2.0,  2.2, 2.5};
// Incident polar angles, degrees: the centres of the exit bins, 2.5 to 87.5 in steps of 5.
constexpr int kExitBins = 18;
constexpr double kBinDegrees = 90.0 / kExitBins;
constexpr std::array<double, kExitBins> kThetas = [] {
  std::array<double, kExitBins> thetas{};
  for (int k = 0; k < kExitBins; ++k) thetas[static_cast<std::size_t>(k)] = (k + 0.5) * kBinDegrees;
  return thetas;
}();
constexpr long kWalks = 100000;

struct Row {
  double sigma, index, mu;
  std::array<double, kExitBins> reflection{}, transmission{};
};

Row tabulate(std::size_t s, std::size_t e, std::size_t t) {
  Row row{kSigmas[s], kIndices[e], std::cos(kThetas[t] * kPi / 180.0)};
  if (row.index == 1.0) return row;  // no interface: nothing scatters
  const MicrosurfaceWalk walk(RoughDielectric{row.index, row.sigma, MicrofacetModel::Multiple});
  std::mt19937_64 random(1000003ULL * s + 1009ULL * e + t + 1);
  const Vec3 wi = direction_from_angles(kThetas[t] * kPi / 180.0, 0.0);
  for (long k = 0; k < kWalks; ++k) {
    const MicrosurfaceExit exit = walk.walk(wi, random);
    if (exit.order < 2) continue;
    const double theta = std::acos(std::min(std::abs(exit.direction.z()), 1.0)) * 180.0 / kPi;
    const int bin = std::min(static_cast<int>(theta / kBinDegrees), kExitBins - 1);
    std::array<double, kExitBins>& tally = exit.direction.z() > 0.0 ? row.reflection : row.transmission;
    tally[static_cast<std::size_t>(bin)] += 1.0;
  }
  for (int b = 0; b < kExitBins; ++b) {  // counts to the bin's mean BSDF: / (walks x its projected solid angle)
    const double lo = std::cos(b * kBinDegrees * kPi / 180.0), hi = std::cos((b + 1) * kBinDegrees * kPi / 180.0);
    const double projected = kPi * (lo * lo - hi * hi);
    row.reflection[static_cast<std::size_t>(b)] /= static_cast<double>(kWalks) * projected;
    row.transmission[static_cast<std::size_t>(b)] /= static_cast<double>(kWalks) * projected;
  }
  return row;
}

std::string format(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

int run(int argc, char** argv) {
  std::string output;
  for (int a = 1; a < argc; ++a) {
    const std::string argument = argv[a];
    if (argument.rfind("--output=", 0) == 0) output = argument.substr(9);
  }
  const std::size_t count = kSigmas.size() * kIndices.size() * kThetas.size();
  std::vector<Row> rows(count);
  std::atomic<std::size_t> next{0}, done{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      const std::size_t s = i / (kIndices.size() * kThetas.size());
      const std::size_t e = (i / kThetas.size()) % kIndices.size();
      rows[i] = tabulate(s, e, i % kThetas.size());
      const std::size_t finished = ++done;
      if (finished % 100 == 0) std::cerr << "microfacet tables: " << finished << " of " << count << " rows\n";
    }
  };
  {
    std::vector<std::jthread> threads;
    const unsigned helpers = std::max(1u, std::thread::hardware_concurrency()) - 1;
    for (unsigned h = 0; h < helpers; ++h) threads.emplace_back(work);
    work();
  }
  std::ostringstream csv;
  csv << "sigma,index,mu_i";
  for (int b = 0; b < kExitBins; ++b) csv << ",r" << b;
  for (int b = 0; b < kExitBins; ++b) csv << ",t" << b;
  csv << "\n";
  for (const Row& row : rows) {
    csv << format(row.sigma) << "," << format(row.index) << "," << format(row.mu);
    for (const double v : row.reflection) csv << "," << format(v);
    for (const double v : row.transmission) csv << "," << format(v);
    csv << "\n";
  }
  if (output.empty()) {
    std::cout << csv.str();
  } else {
    std::ofstream(output) << csv.str();
    std::cerr << "microfacet tables: wrote " << output << "\n";
  }
  return 0;
}

}  // namespace
}  // namespace skinlayer

int main(int argc, char** argv) { return skinlayer::run(argc, argv); }
