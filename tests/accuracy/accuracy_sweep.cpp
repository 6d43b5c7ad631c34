// The pointwise accuracy sweep of issue 10: every parameter of the grid varied about a sharp base material, plus
// interacting extremes, each solved at the automatic resolution and judged point by point against a converged solve
// (core/reference/point_accuracy.h). Writes Markdown (docs/accuracy.md through `cmake --build build --target
// accuracy-doc`, or to stdout); progress and the verdict go to stderr. Without --report, exit status 1 if any
// material errs by more than 1%.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/process/heap_retention.h"
#include "core/conventions.h"
#include "core/reference/point_accuracy.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

struct SweepCase {
  std::string parameter;  // the parameter varied ("base" and "interacting" for the others; "sample" for the grid's)
  std::string value;
  Material material;
  std::vector<std::pair<std::string, std::string>> grid = {};  // a grid sample's value of each parameter
};

// Base: sharp interfaces, a clear layer, forward scattering, half albedo, air below.
Material base_material() {
  Material m;
  m.sigma = 0.2;
  m.eta = 1.4;
  m.tau = optical_depth_from_transparency(0.2);
  m.g = 0.5;
  m.albedo = 0.5;
  return m;
}

std::string shortest(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::vector<SweepCase> sweep_cases() {
  std::vector<SweepCase> cases;
  const auto vary = [&](const std::string& name, std::initializer_list<double> values,
                        const std::function<void(Material&, double)>& set) {
    for (const double v : values) {
      Material m = base_material();
      set(m, v);
      cases.push_back({name, shortest(v), m});
    }
  };
  cases.push_back({"base", "σ 0.2 η 1.4 T 0.2 g 0.5 Ω 0.5 air", base_material()});
  vary("sigma", {0.05, 0.1, 0.3, 0.5, 1.0}, [](Material& m, double v) { m.sigma = v; });
  vary("eta", {1.05, 1.2, 2.0}, [](Material& m, double v) { m.eta = v; });
  vary("T", {0.0, 0.05, 0.5, 0.9}, [](Material& m, double v) { m.tau = optical_depth_from_transparency(v); });
  vary("g", {0.0, 0.9}, [](Material& m, double v) { m.g = v; });
  vary("albedo", {0.0, 1.0}, [](Material& m, double v) { m.albedo = v; });
  // Named variants of the base, several parameters at once: sharp interfaces with thin or forward-scattering layers.
  const auto add = [&](const std::string& parameter, const std::string& value, const std::string& sigma,
                       const std::string& eta, const std::string& transparency, const std::string& g,
                       const std::string& albedo, const std::string& bottom) {
    Material m = base_material();
    if (!sigma.empty()) m.sigma = std::stod(sigma);
    if (!eta.empty()) m.eta = std::stod(eta);
    if (!transparency.empty()) m.tau = optical_depth_from_transparency(std::stod(transparency));
    if (!g.empty()) m.g = std::stod(g);
    if (!albedo.empty()) m.albedo = std::stod(albedo);
    if (!bottom.empty()) m.bottom = parse_bottom(bottom);
    cases.push_back({parameter, value, m});
  };
  add("bottom", "matched", "", "", "", "", "", "matched");
  add("bottom", "lambert:0.8", "", "", "", "", "", "lambert:0.8");
  {
    Material m = base_material();
    m.bottom.sigma = 0.1;
    m.bottom.eta = 1.2;
    cases.push_back({"bottom", "air, unlike the top (σ3 0.1, η3 1.2)", m});
  }
  add("interacting", "σ 0.05 T 0.9 g 0.9 Ω 1", "0.05", "", "0.9", "0.9", "1", "");
  add("interacting", "σ 0.05 T 0.5 g 0.9 Ω 1 matched", "0.05", "", "0.5", "0.9", "1", "matched");
  add("interacting", "σ 0.1 η 1.05 T 0.5", "0.1", "1.05", "0.5", "", "", "");
  return cases;
}

// A seeded sample of issue 10's whole factorial grid, 6 sigma x 4 eta x 5 T x 3 g x 3 Omega x 4 bottoms = 4320
// materials, drawn without repetition (std::mt19937 is specified bit for bit, so the draw is the same everywhere).
std::vector<SweepCase> factorial_sample(int count) {
  const std::vector<double> sigmas = {0.05, 0.1, 0.2, 0.3, 0.5, 1.0};
  const std::vector<double> etas = {1.05, 1.2, 1.4, 2.0};
  const std::vector<double> transparencies = {0.0, 0.05, 0.2, 0.5, 0.9};
  const std::vector<double> gs = {0.0, 0.5, 0.9};
  const std::vector<double> albedos = {0.0, 0.5, 1.0};
  const std::vector<std::string> bottoms = {"air", "air σ3 0.1 η3 1.2", "matched", "lambert:0.8"};
  const std::size_t total =
      sigmas.size() * etas.size() * transparencies.size() * gs.size() * albedos.size() * bottoms.size();
  std::mt19937 draw(20261130u);
  std::vector<std::size_t> taken;
  std::vector<SweepCase> cases;
  while (static_cast<int>(cases.size()) < count) {
    std::size_t index = draw() % total;
    if (std::find(taken.begin(), taken.end(), index) != taken.end()) continue;
    taken.push_back(index);
    const auto pick = [&index](std::size_t size) {
      const std::size_t k = index % size;
      index /= size;
      return k;
    };
    Material m;
    m.sigma = sigmas[pick(sigmas.size())];
    m.eta = etas[pick(etas.size())];
    const double transparency = transparencies[pick(transparencies.size())];
    m.tau = optical_depth_from_transparency(transparency);
    m.g = gs[pick(gs.size())];
    m.albedo = albedos[pick(albedos.size())];
    const std::string bottom = bottoms[pick(bottoms.size())];
    if (bottom.rfind("air σ3", 0) == 0) {
      m.bottom.sigma = 0.1;
      m.bottom.eta = 1.2;
    } else if (bottom != "air") {
      m.bottom = parse_bottom(bottom);
    }
    const std::string value = "σ " + shortest(m.sigma) + " η " + shortest(m.eta) + " T " + shortest(transparency) +
                              " g " + shortest(m.g) + " Ω " + shortest(m.albedo) + " " + bottom;
    cases.push_back({"sample",
                     value,
                     m,
                     {{"σ", shortest(m.sigma)},
                      {"η", shortest(m.eta)},
                      {"T", shortest(transparency)},
                      {"g", shortest(m.g)},
                      {"Ω", shortest(m.albedo)},
                      {"bottom", bottom}}});
  }
  return cases;
}

std::string degrees(double radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", radians_to_degrees(radians));
  return text;
}

}  // namespace
}  // namespace skinlayer

constexpr int kGridSample = 32;  // materials drawn from the whole grid

int main(int argc, char** argv) {
  using namespace skinlayer;
  retain_freed_heap_memory();
  std::string output;
  SolveOptions options;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg.rfind("--report=", 0) == 0) output = arg.substr(9);
    if (arg == "--all-ordinates") options.exact_unscattered = false;  // the paper's method, for comparison
  }
  const std::vector<double> incidence = {0.0, degrees_to_radians(30.0), degrees_to_radians(60.0),
                                         degrees_to_radians(80.0)};
  std::vector<SweepCase> cases = sweep_cases();
  const std::size_t one_at_a_time = cases.size();
  for (SweepCase& c : factorial_sample(kGridSample)) cases.push_back(std::move(c));
  std::ostringstream md;
  md << "# Pointwise accuracy at the automatic resolution" << (options.exact_unscattered ? "" : " (all ordinates)")
     << "\n\n"
     << "Generated by `cmake --build build --target accuracy-doc` (tests/accuracy/accuracy_sweep.cpp). Each material "
        "is "
        "solved at the automatic resolution and judged at single direction pairs against a converged solve (N 192, a "
        "table grid twice as fine, at least 95 nodes): θi 0, 30, 60, 80°; φ 0, 90, 180°; θo every 0.5° plus 0.05° "
        "steps within 3° of the "
        "normal, the mirror and the straight-through directions. Judged: every point whose converged BRDF "
        "(subsurface) or BTDF exceeds 1e-3 of the material's peak of that quantity (a quantity whose peak is under "
        "1e-12 1/sr, such as the subsurface BRDF of a layer that does not scatter over a matched bottom, is 0 up to "
        "round-off and is not judged). The unscattered part, exact in "
        "both, is judged against closed forms and a brute-force integral in "
        "tests/core/unscattered/unscattered_light_test.cpp. "
        "The first rows vary one parameter at a time about a sharp base (σ 0.2, η 1.4, T 0.2, g 0.5, Ω 0.5, air) "
        "plus interacting extremes; the rows marked `sample` are a seeded draw of "
     << kGridSample
     << " materials from the issue's whole factorial grid (σ 0.05, 0.1, 0.2, 0.3, 0.5, 1 × η 1.05, 1.2, 1.4, 2 × T "
        "0, 0.05, 0.2, 0.5, 0.9 × g 0, 0.5, 0.9 × Ω 0, 0.5, 1 × bottoms air, air unlike the top, matched, lambert), "
        "summarized per grid value at the end."
     << (options.exact_unscattered
             ? " The same sweep with every path on the ordinates, as the paper publishes the method (`accuracy_sweep "
               "--all-ordinates`), is [accuracy-all-ordinates.md](accuracy-all-ordinates.md)."
             : "")
     << "\n\n"
     << "N and K are the automatic resolution's ordinates per hemisphere and table grid nodes "
        "(`refracted_lobe_ordinates` and `lobe_table_size` in core/solver.cpp). Machine: "
     << std::thread::hardware_concurrency() << " logical cores; solve times are one thread, one run.\n\n"
     << "| parameter | value | N | K | solve ms | points judged | worst error | where (θi, θo, φ) | value / converged "
        "[1/sr] |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, PointError> worst_per_parameter;
  std::map<std::pair<std::string, std::string>, std::pair<PointError, std::string>> worst_per_grid_value;
  double worst = 0.0;
  int materials_within = 0;
  const auto started = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const SweepCase& c = cases[k];
    std::cerr << "[" << k + 1 << "/" << cases.size() << "] " << c.parameter << " " << c.value << "\n";
    const PointAccuracy a = point_accuracy(c.material, incidence, options);
    const PointError& w = a.worst;
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %s | %d | %d | %.1f | %d | %.3f%% | %s %s, %s, %s | %.5g / %.5g |\n",
                  c.parameter.c_str(), c.value.c_str(), a.ordinates, a.table_size, 1e3 * a.solve_seconds, a.judged,
                  100.0 * w.relative, w.transmission ? "BTDF" : "BRDF", degrees(w.theta_i).c_str(),
                  degrees(w.theta_o).c_str(), degrees(w.phi).c_str(), w.value, w.converged);
    md << row;
    if (w.relative >= worst_per_parameter[c.parameter].relative) worst_per_parameter[c.parameter] = w;
    for (const auto& key : c.grid) {
      auto& [grid_worst, grid_where] = worst_per_grid_value[key];
      if (w.relative >= grid_worst.relative) {
        grid_worst = w;
        grid_where = c.value;
      }
    }
    worst = std::max(worst, w.relative);
    if (w.relative <= 0.01) ++materials_within;
  }
  md << "\n## Worst error per parameter\n\n| parameter | worst error |\n|---|---|\n";
  for (const auto& [parameter, w] : worst_per_parameter) {
    char row[128];
    std::snprintf(row, sizeof row, "| %s | %.3f%% |\n", parameter.c_str(), 100.0 * w.relative);
    md << row;
  }
  md << "\n## Worst error per grid value (the " << cases.size() - one_at_a_time
     << " sampled materials)\n\n| parameter | value | worst error | material | where (θi, θo, φ) "
        "|\n|---|---|---|---|---|\n";
  for (const auto& [key, entry] : worst_per_grid_value) {
    const auto& [w, material] = entry;
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %s | %.3f%% | %s | %s %s, %s, %s |\n", key.first.c_str(), key.second.c_str(),
                  100.0 * w.relative, material.c_str(), w.transmission ? "BTDF" : "BRDF", degrees(w.theta_i).c_str(),
                  degrees(w.theta_o).c_str(), degrees(w.phi).c_str());
    md << row;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  md << "\nOverall worst: " << shortest(100.0 * worst) << "% (criterion: 1%); " << materials_within << " of "
     << cases.size() << " materials within 1%. Sweep wall time " << shortest(seconds) << " s.\n";
  if (output.empty()) {
    std::cout << md.str();
  } else {
    std::ofstream(output) << md.str();
    std::cerr << "wrote " << output << "\n";
  }
  std::cerr << (worst <= 0.01 ? "every material within 1%\n" : "the 1% criterion is not met everywhere\n");
  // Writing the report (the accuracy-doc target) succeeds whatever it says; the console check fails above 1%.
  return worst <= 0.01 || !output.empty() ? 0 : 1;
}
