// The generator of core/data/microfacet_multiple_scattering.csv (kept xz-packed, in .tar.xz) and
// core/data/microfacet_single_scattering_loss.csv:
// the light a rough dielectric interface scatters more than once on its microsurface, its lobe on a grid of directions,
// and the light single scattering leaves, which that lobe carries (core/interfaces/multiple_scattering_table.h).
//
// For each Beckmann sigma and interface index E > 1 of the grids below, and each incident polar angle of the angle
// grid from above and from below, the next-event estimate of core/reference/multiple_scattering_estimate.h (walks
// until kWalksWithMeetings have met the microsurface twice or more) gives the BSDF at every exit polar angle of the
// same grid, back and beyond, and at every azimuth of the azimuth grid. Reciprocity pairs the estimates, and their
// mean is taken:
//   reflection from above (kernel 0) and from below (kernel 1):  f(i, o, phi) = (f(i -> o) + f(o -> i)) / 2,
//   transmission from above (kernel 2):  f(i, o, phi) = (f_above(i -> o) + E^2 f_below(o -> i)) / 2.
// Its energy is matched to the single scattering's loss l at the grid angles (core's slope integrals;
// core/interfaces/multiple_scattering_energy.h), which the loss table holds, and the lobe table holds its shape,
// f(i, o) / sqrt(l(i) l(o)). A row holds one kernel and pair of polar angles over the azimuths, reflection only for
// theta_o >= theta_i (the other half is its mirror): a unit (the row's largest value / kSteps) and each value as a
// whole number of units, rounded. A value below kNegligible of its kernel's largest is written as 0, and a row of
// zeros is left out.
//
//   cmake --build build --target microfacet-tables      (about 25 minutes on 2 cores)
//
// writes both CSV files in the source tree; --sigmas= and --etas= take other grids (comma lists) for trials,
// --output= and --loss-output= other files. The walks are seeded from each estimate's indices, so the tables are
// the same on every run, whatever the thread count.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <span>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/multiple_scattering_energy.h"
#include "core/interfaces/multiple_scattering_table.h"
#include "core/reference/multiple_scattering_estimate.h"

namespace skinlayer {
namespace {

std::vector<double> kSigmas = {0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0};
// About 4 degrees of critical angle asin(1/E) apart, where the light from inside starts to be totally reflected.
std::vector<double> kEtas = {1.05, 1.1, 1.15, 1.2, 1.27, 1.33, 1.4, 1.5, 1.6, 1.75, 1.95, 2.2, 2.5};
// Azimuths phi = phi_o - phi_i in degrees, ascending, closest at the forward plane (180), where the lobe is sharp.
constexpr std::array<double, 26> kPhis = {0.0,   30.0,  60.0,  90.0,  95.0,  100.0, 105.0, 110.0, 115.0,
                                          120.0, 125.0, 130.0, 135.0, 140.0, 145.0, 150.0, 155.0, 160.0,
                                          164.0, 168.0, 171.5, 174.5, 177.0, 178.5, 179.5, 180.0};
// Polar angles 0 to 90 degrees in steps of 5; the grazing node is estimated at 89.5 degrees (no light leaves along
// the horizon itself, where the BSDF is the limit of its values beside it).
constexpr int kAngles = 19;
constexpr long kWalksWithMeetings = 10'000;
constexpr double kNegligible = 1e-4;
constexpr double kSteps = 999.0;

double grid_degrees(int k) { return 5.0 * k; }
std::vector<double> radians(std::span<const double> degrees) {
  std::vector<double> result;
  for (const double d : degrees) result.push_back(d * kPi / 180.0);
  return result;
}
double estimated_degrees(int k) { return k == kAngles - 1 ? 89.5 : grid_degrees(k); }

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> values;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) values.push_back(std::stod(item));
  return values;
}

// One (sigma, eta): the estimates from above and below at every incident angle.
struct Block {
  std::array<std::vector<MultipleScatteringEstimate>, 2> from;  // [0] above, [1] below; [incident angle]
};

// The lobe of one (sigma, E) on the grid, each kernel the mean of the reciprocal estimates: reflection from above and
// from below, f(i, o) = (f(i -> o) + f(o -> i)) / 2, and transmission from above, (f_above(i -> o) + E^2 f_below(o ->
// i)) / 2. At normal incidence the azimuth means nothing, and the azimuths' mean is each one's value.
MultipleScatteringSamples reciprocal_lobe(const Block& block, double eta) {
  const std::size_t azimuths = kPhis.size();
  const auto estimate = [&](int s, int i, int e, int o, std::size_t j) {
    const MultipleScatteringEstimate& from = block.from[static_cast<std::size_t>(s)][static_cast<std::size_t>(i)];
    if (i != 0) return from.at(e, static_cast<std::size_t>(o), j);
    double mean = 0.0;
    for (std::size_t k = 0; k < azimuths; ++k) mean += from.at(e, static_cast<std::size_t>(o), k) / azimuths;
    return mean;
  };
  MultipleScatteringSamples lobe;
  lobe.azimuths = radians(kPhis);
  for (int kernel = 0; kernel < 3; ++kernel) {
    Eigen::MatrixXd& k = lobe.kernels[static_cast<std::size_t>(kernel)];
    k.resize(kAngles * kAngles, static_cast<Eigen::Index>(azimuths));
    for (int i = 0; i < kAngles; ++i) {
      for (int o = 0; o < kAngles; ++o) {
        for (std::size_t j = 0; j < azimuths; ++j) {
          k(i * kAngles + o, static_cast<Eigen::Index>(j)) =
              kernel < 2 ? 0.5 * (estimate(kernel, i, 0, o, j) + estimate(kernel, o, 0, i, j))
                         : 0.5 * (estimate(0, i, 1, o, j) + eta * eta * estimate(1, o, 1, i, j));
        }
      }
    }
  }
  return lobe;
}

// The light single scattering leaves at the grid angles (core's slope integrals), from above or from below.
std::vector<double> single_scattering_losses(double sigma, double eta, const std::vector<double>& angles, bool above) {
  const RoughDielectric interface { eta, sigma, MicrofacetModel::Multiple };
  std::vector<double> losses;
  for (const double theta : angles) {
    const Vec3 wi = direction_from_angles(theta, 0.0);
    losses.push_back(
        std::max(0.0, single_scattering_albedo(interface, above ? wi : Vec3(wi.x(), wi.y(), -wi.z())).loss()));
  }
  return losses;
}

std::string format(double value, int digits = 6) {
  if (value == 0.0) return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

int run(int argc, char** argv) {
  std::string output = "microfacet_multiple_scattering.csv", loss_output = "microfacet_single_scattering_loss.csv";
  for (int a = 1; a < argc; ++a) {
    const std::string argument = argv[a];
    if (argument.rfind("--output=", 0) == 0) output = argument.substr(9);
    if (argument.rfind("--loss-output=", 0) == 0) loss_output = argument.substr(14);
    if (argument.rfind("--sigmas=", 0) == 0) kSigmas = parse_list(argument.substr(9));
    if (argument.rfind("--etas=", 0) == 0) kEtas = parse_list(argument.substr(7));
  }
  std::vector<double> angles;
  for (int k = 0; k < kAngles; ++k) angles.push_back(estimated_degrees(k) * kPi / 180.0);
  const std::vector<double> phis = radians(kPhis);
  const std::size_t blocks = kSigmas.size() * kEtas.size();
  std::vector<Block> results(blocks);
  for (Block& block : results) {
    for (auto& side : block.from) side.resize(kAngles);
  }
  const std::size_t count = blocks * 2 * kAngles;
  std::atomic<std::size_t> next{0}, done{0};
  const auto work = [&] {
    for (std::size_t task = next++; task < count; task = next++) {
      const std::size_t b = task / (2 * kAngles), side = (task / kAngles) % 2, i = task % kAngles;
      const double sigma = kSigmas[b / kEtas.size()], eta = kEtas[b % kEtas.size()];
      MultipleScatteringEstimateOptions options;
      options.walks_with_meetings = kWalksWithMeetings;
      options.seed = 1 + task;
      results[b].from[side][i] = estimate_multiple_scattering(RoughDielectric{eta, sigma, MicrofacetModel::Multiple},
                                                              angles[i], side == 0, angles, phis, options);
      const std::size_t finished = ++done;
      if (finished % 50 == 0 || finished == count) {
        std::cerr << "microfacet tables: " << finished << " of " << count << " estimates\n";
      }
    }
  };
  {
    std::vector<std::jthread> threads;
    const unsigned helpers = std::max(1u, std::thread::hardware_concurrency()) - 1;
    for (unsigned h = 0; h < helpers; ++h) threads.emplace_back(work);
    work();
  }

  std::ostringstream csv, loss_csv;
  csv << "sigma,eta,kernel,theta_i,theta_o,unit";
  for (std::size_t j = 0; j < kPhis.size(); ++j) csv << ",p" << format(kPhis[j]);
  csv << "\n";
  loss_csv << "sigma,eta,side";
  for (int k = 0; k < kAngles; ++k) loss_csv << ",l" << format(grid_degrees(k));
  loss_csv << "\n";
  long written = 0, left_out = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const double sigma = kSigmas[b / kEtas.size()], eta = kEtas[b % kEtas.size()];
    // The walk's lobe, carrying exactly the light single scattering leaves, then as shapes: f / sqrt(l_i l_o).
    MultipleScatteringSamples lobe = reciprocal_lobe(results[b], eta);
    const std::vector<double> above = single_scattering_losses(sigma, eta, angles, true);
    const std::vector<double> below = single_scattering_losses(sigma, eta, angles, false);
    match_multiple_scattering_energy(lobe, above, below, eta);
    for (int side = 0; side < 2; ++side) {
      loss_csv << format(sigma) << "," << format(eta) << "," << side;
      for (const double l : side == 0 ? above : below) loss_csv << "," << format(l, 8);
      loss_csv << "\n";
    }
    for (int kernel = 0; kernel < 3; ++kernel) {
      const std::vector<double>& incident = kernel == 1 ? below : above;
      const std::vector<double>& exit = kernel == 0 ? above : below;
      Eigen::MatrixXd shape = lobe.kernels[static_cast<std::size_t>(kernel)];
      for (int i = 0; i < kAngles; ++i) {
        for (int o = 0; o < kAngles; ++o) {
          const double norm = std::sqrt(incident[static_cast<std::size_t>(i)] * exit[static_cast<std::size_t>(o)]);
          shape.row(i * kAngles + o) *= norm > 0.0 ? 1.0 / norm : 0.0;
        }
      }
      const double largest = shape.maxCoeff();
      for (int i = 0; i < kAngles; ++i) {
        for (int o = kernel < 2 ? i : 0; o < kAngles; ++o) {
          Eigen::RowVectorXd row = shape.row(i * kAngles + o);
          row = (row.array() > kNegligible * largest).select(row, 0.0);
          if (row.maxCoeff() <= 0.0) {
            ++left_out;
            continue;
          }
          ++written;
          const double unit = row.maxCoeff() / kSteps;
          csv << format(sigma) << "," << format(eta) << "," << kernel << "," << format(grid_degrees(i)) << ","
              << format(grid_degrees(o)) << "," << format(unit, 4);
          for (const double v : row) csv << "," << std::lround(v / unit);
          csv << "\n";
        }
      }
    }
  }
  std::cerr << "microfacet tables: " << written << " rows written, " << left_out << " negligible rows left out\n";
  std::ofstream(output) << csv.str();
  std::ofstream(loss_output) << loss_csv.str();
  std::cerr << "microfacet tables: wrote " << output << " and " << loss_output << "\n";
  return 0;
}

}  // namespace
}  // namespace skinlayer

int main(int argc, char** argv) { return skinlayer::run(argc, argv); }
