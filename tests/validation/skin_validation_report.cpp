// Experimental validation of the spectral skin (issue 25; Stam 2001's future work): fits every measured spectrum of
// tests/reference/nist_skin_reflectance.csv as `skinlayer match --spectrum` does (400-700 nm, 8 degrees, the default
// top interface) and writes docs/skin-validation.md (the residuals' distribution, each subject's fit) and
// docs/skin-validation-fits.png (the best, median and worst fits against the measurements).
//   Run: cmake --build build --target skin-validation-doc
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/figures/font.h"
#include "app/figures/plot_style.h"
#include "app/figures/xy_plot.h"
#include "app/process/parallel_for.h"
#include "app/render/png_export.h"
#include "core/conventions.h"
#include "core/fit/skin_fit.h"

namespace {

using skinlayer::SkinSpectrumFit;

struct Subject {
  std::string name;
  std::vector<double> reflectance;
  SkinSpectrumFit fit;
  double seconds = 0.0;
};

std::string formatted(const char* format, auto... values) {
  char text[512];
  std::snprintf(text, sizeof text, format, values...);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: skin_validation_report NIST_CSV DOCS_DIR\n");
    return 2;
  }
  std::ifstream file(argv[1]);
  if (!file) {
    std::fprintf(stderr, "skin_validation_report: cannot read %s\n", argv[1]);
    return 1;
  }
  std::vector<double> wavelengths;
  std::vector<Subject> subjects;
  std::string line, field;
  std::getline(file, line);
  {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // the file has CRLF line ends
    std::stringstream header(line);
    std::getline(header, field, ',');
    while (std::getline(header, field, ',')) subjects.push_back({field, {}, {}, 0.0});
  }
  while (std::getline(file, line)) {
    std::stringstream row(line);
    std::getline(row, field, ',');
    wavelengths.push_back(std::stod(field));
    for (Subject& s : subjects) {
      std::getline(row, field, ',');
      s.reflectance.push_back(std::stod(field));
    }
  }
  for (Subject& s : subjects) {
    const auto start = std::chrono::steady_clock::now();
    s.fit = skinlayer::fit_skin_spectrum(wavelengths, s.reflectance, skinlayer::degrees_to_radians(8.0), 400.0, 700.0,
                                         skinlayer::Material{}, skinlayer::parallel_for_threads);
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "%s: RMS %.4f (%.1f s)\n", s.name.c_str(), s.fit.rms, s.seconds);
  }
  std::vector<const Subject*> order;
  for (const Subject& s : subjects) order.push_back(&s);
  std::sort(order.begin(), order.end(), [](const Subject* a, const Subject* b) { return a->fit.rms < b->fit.rms; });
  const Subject& best = *order.front();
  const Subject& median = *order[order.size() / 2];
  const Subject& worst = *order.back();

  const std::filesystem::path docs(argv[2]);
  // The figure: measured points and fitted curves of the best, median and worst fits.
  skinlayer::figures::XyPlot plot;
  plot.title = "NIST skin spectra against the fitted spectral skin (8°, 400-700 nm)";
  plot.x_label = "wavelength, nm";
  plot.y_label = "reflectance";
  plot.x_min = 400.0;
  plot.x_max = 700.0;
  plot.x_tick = 50.0;
  plot.width = 900;
  plot.height = 420;
  std::size_t color = 0;
  for (const auto& [what, subject] : {std::pair{"best", &best}, std::pair{"median", &median}, {"worst", &worst}}) {
    skinlayer::figures::XySeries fitted{
        formatted("%s fit, %s (RMS %.4f)", what, subject->name.c_str(), subject->fit.rms),
        skinlayer::figures::curve_color(color),
        {},
        {},
        {}};
    skinlayer::figures::XySeries measured{"", skinlayer::figures::curve_color(color), {}, {}, {}};
    for (std::size_t k = 0; k < subject->fit.wavelengths_nm.size(); ++k) {
      fitted.curve.push_back({subject->fit.wavelengths_nm[k], subject->fit.fitted[k]});
      if (k % 3 == 0) measured.points.push_back({subject->fit.wavelengths_nm[k], subject->fit.measured[k], 0.0});
    }
    plot.series.push_back(fitted);
    plot.series.push_back(measured);
    ++color;
  }
  const skinlayer::figures::Font font;
  skinlayer::write_png(skinlayer::figures::draw_xy_plot(plot, font), (docs / "skin-validation-fits.png").string());

  // The report.
  std::vector<double> rms;
  for (const Subject* s : order) rms.push_back(s->fit.rms);
  const auto range_of = [&](auto member) {
    double lo = 1e300, hi = -1e300;
    for (const Subject& s : subjects) {
      lo = std::min(lo, member(s.fit.skin));
      hi = std::max(hi, member(s.fit.skin));
    }
    return formatted("%.3g–%.3g", lo, hi);
  };
  int at_scattering_bound = 0, no_eumelanin = 0;
  double seconds = 0.0, slowest = 0.0;
  for (const Subject& s : subjects) {
    at_scattering_bound += s.fit.skin.scattering >= 4.0 - 1e-9;
    no_eumelanin += s.fit.skin.eumelanin <= 1e-9;
    seconds += s.seconds;
    slowest = std::max(slowest, s.seconds);
  }
  std::ofstream md(docs / "skin-validation.md");
  md << "# The spectral skin against measured skin\n\n"
     << "Regenerate with `cmake --build build --target skin-validation-doc`. Each of the " << subjects.size()
     << " NIST spectra of `tests/reference/nist_skin_reflectance.csv` (directional-hemispherical reflectance, "
        "integrating sphere, specular included) fitted as `skinlayer match --spectrum FILE --theta-i 8` fits it: "
        "all six skin parameters, least squares in reflectance at the file's 3 nm wavelengths over 400–700 nm "
        "(101 wavelengths), the default top interface (σ 0.5, η 1.4).\n\n"
     << formatted(
            "**RMS residual:** median %.4f, best %.4f, worst %.4f; %d of %zu under 0.02 (targets: median ≤ 0.02, "
            "worst ≤ 0.05).\n\n",
            rms[rms.size() / 2], rms.front(), rms.back(),
            static_cast<int>(std::count_if(rms.begin(), rms.end(), [](double r) { return r <= 0.02; })), rms.size())
     << formatted("**Time:** %.1f s per fit on average, %.1f s the slowest, on %u hardware threads.\n\n",
                  seconds / static_cast<double>(subjects.size()), slowest, std::thread::hardware_concurrency())
     << "**Fitted parameters' ranges:** melanin " << range_of([](const auto& k) { return k.melanin; })
     << ", eumelanin share " << range_of([](const auto& k) { return k.eumelanin; }) << ", blood "
     << range_of([](const auto& k) { return k.blood; }) << ", oxygenation "
     << range_of([](const auto& k) { return k.oxygenation; }) << ", epidermis "
     << range_of([](const auto& k) { return k.epidermis; }) << " mm, scattering scale "
     << range_of([](const auto& k) { return k.scattering; }) << ".\n\n"
     << formatted("%d fits rest on the scattering scale's upper bound (4) and %d on a zero eumelanin share.\n\n",
                  at_scattering_bound, no_eumelanin)
     << "![best, median and worst fits](skin-validation-fits.png)\n\n"
     << "| subject | RMS | melanin | eumelanin | blood | oxygenation | epidermis mm | scattering |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const Subject* s : order) {
    const skinlayer::SkinParameters& k = s->fit.skin;
    md << formatted("| %s | %.4f | %.4f | %.3f | %.4f | %.3f | %.4f | %.3f |\n", s->name.c_str(), s->fit.rms, k.melanin,
                    k.eumelanin, k.blood, k.oxygenation, k.epidermis, k.scattering);
  }
  std::fprintf(stderr, "wrote %s\n", (docs / "skin-validation.md").c_str());
  return 0;
}
