#include "app/figures/skin_figures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/figures/model_spheres.h"
#include "app/figures/xy_plot.h"
#include "app/material/material_flag_text.h"
#include "app/material/picture_metadata.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_profile.h"
#include "app/solution/material_solve.h"
#include "app/text/numbers.h"
#include "core/conventions.h"
#include "core/skin/skin_spectrum.h"

namespace skinlayer::figures {
namespace {

// The --skin value of a curve, with ';' for ',' so that it is one CSV field.
std::string skin_field(const SkinParameters& skin) {
  std::string spec = format_skin_spec(skin);
  std::replace(spec.begin(), spec.end(), ',', ';');
  return spec;
}

std::string material_fields(const FigureCurve& curve) {
  return skin_field(*curve.skin) + "," + text::format_shortest(curve.params.sigma) + "," +
         text::format_shortest(curve.params.eta);
}

// The first curve's skin as the picture's material, and the values the figure varies.
PngText skin_metadata(const FigureSpec& spec) {
  const FigureCurve& first = spec.curves.front();
  MaterialDocument material;
  material.layer = first.params.material();
  material.skin = first.skin;
  material.name = spec.name;
  material.description = spec.title + " (the first curve's material)";
  return picture_metadata(material, figure_settings(spec));
}

std::ofstream open_csv(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  return out;
}

void close_csv(std::ofstream& out, const std::filesystem::path& path) {
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

// A skin figure's plot frame, twice as wide as high; the subtitle's fixed parameters are in the CSV and the index's
// caption.
XyPlot skin_plot(const FigureSpec& spec, const char* x_label, const char* y_label, double x_min, double x_max,
                 double x_tick, int size) {
  XyPlot plot;
  plot.title = spec.title;
  plot.x_label = x_label;
  plot.y_label = y_label;
  plot.x_min = x_min;
  plot.x_max = x_max;
  plot.x_tick = x_tick;
  plot.width = size * 2;
  plot.height = size;
  return plot;
}

FigureSize build_spectra(const FigureSpec& spec, const std::filesystem::path& dir, const Font& font, int size) {
  const std::vector<double> wavelengths = wavelength_grid(400.0, 700.0, 5.0);
  XyPlot plot = skin_plot(spec, "wavelength, nm", "reflectance", 400.0, 700.0, 50.0, size);
  const std::filesystem::path csv_path = dir / (spec.name + ".csv");
  std::ofstream csv = open_csv(csv_path);
  csv << "curve,parameter,value,theta_i,wavelength_nm,reflectance,skin,sigma,eta\n";
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    const FigureCurve& curve = spec.curves[k];
    const double theta[1] = {degrees_to_radians(curve.theta_i_deg)};
    const std::vector<std::vector<DirectionalAlbedo>> rows =
        skin_directional_albedo(*curve.skin, curve.params.material(), wavelengths, theta, options);
    XySeries series{curve.label, curve_color(k), {}, {}, {}};
    for (std::size_t w = 0; w < wavelengths.size(); ++w) {
      const double reflectance = rows[w].front().reflectance();
      series.curve.push_back({wavelengths[w], reflectance});
      csv << curve.label << ',' << spec.parameter << ',' << curve.value << ','
          << text::format_shortest(curve.theta_i_deg) << ',' << text::format_shortest(wavelengths[w]) << ','
          << text::format_number(reflectance) << ',' << material_fields(curve) << '\n';
    }
    plot.series.push_back(std::move(series));
  }
  close_csv(csv, csv_path);
  const Image image = draw_xy_plot(plot, font);
  write_png(image, (dir / (spec.name + ".png")).string(), {skin_metadata(spec)});
  return {image.width, image.height};
}

FigureSize build_spheres(const FigureSpec& spec, const std::filesystem::path& dir, const Font& font, int size) {
  const std::filesystem::path csv_path = dir / (spec.name + ".csv");
  std::ofstream csv = open_csv(csv_path);
  csv << "curve,parameter,value,theta_i,reflectance_r,reflectance_g,reflectance_b,skin,sigma,eta\n";
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  for (const FigureCurve& curve : spec.curves) {  // the colour at the sphere's centre under a white furnace
    ColorMaterial material{curve.params.material(), {1.0, 1.0, 1.0}, {}, SubsurfaceModel::Stam, curve.skin};
    const ColorTables tables = solve_color(material, 0.0, options);
    csv << curve.label << ',' << spec.parameter << ',' << curve.value << ",0";
    for (int c = 0; c < 3; ++c) csv << ',' << text::format_number(tables.albedo[c].reflectance());
    csv << ',' << material_fields(curve) << '\n';
  }
  close_csv(csv, csv_path);
  const Image image = draw_model_spheres(spec, font, std::max(size * 7 / 16, 64));
  write_png(image, (dir / (spec.name + ".png")).string(), {skin_metadata(spec)});
  return {image.width, image.height};
}

// log10 R(r) + 4 of each skin at 650, 550 and 450 nm (R in 1/mm^2), at the profile command's resolution, so that
// `skinlayer profile --skin ... --wavelength W --annuli 0.2:20` gives back every CSV value.
FigureSize build_profiles(const FigureSpec& spec, const std::filesystem::path& dir, const Font& font, int size) {
  XyPlot plot = skin_plot(spec, "r, mm", "log10 R + 4 (R in 1/mm²)", 0.0, 4.0, 0.5, size);
  const std::filesystem::path csv_path = dir / (spec.name + ".csv");
  std::ofstream csv = open_csv(csv_path);
  csv << "curve,parameter,value,wavelength_nm,r_inner_mm,r_outer_mm,reflectance,skin,sigma,eta\n";
  struct Band {
    double wavelength;
    const char* name;
    std::array<int, 3> color;
  };
  constexpr std::array<Band, 3> kBands = {
      {{650.0, "650 nm", {200, 40, 40}}, {550.0, "550 nm", {40, 150, 40}}, {450.0, "450 nm", {40, 70, 200}}}};
  std::vector<double> edges;
  for (int i = 0; i <= 20; ++i) edges.push_back(text::decimal_multiple(0.2, i));  // as profile --annuli 0.2:20
  ProfileRequest request;
  request.options.parallel_for = parallel_for_threads;
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    const FigureCurve& curve = spec.curves[k];
    MaterialDocument document;
    document.layer = curve.params.material();
    document.skin = curve.skin;
    const double shade = 1.0 - 0.3 * static_cast<double>(k);  // fair bright, dark deep
    for (const Band& band : kBands) {
      const DocumentProfile profile =
          document_profile_in_annuli(skin_document_at_wavelength(document, band.wavelength), edges, request);
      const Rgba color{static_cast<std::uint8_t>(band.color[0] * shade),
                       static_cast<std::uint8_t>(band.color[1] * shade),
                       static_cast<std::uint8_t>(band.color[2] * shade), 255};
      XySeries series{curve.label + " " + band.name, color, {}, {}, {}};
      for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
        const double value = profile.reflectance.front()[i];
        series.curve.push_back(
            {0.5 * (edges[i] + edges[i + 1]), std::max(0.0, std::log10(std::max(value, 1e-300)) + 4.0)});
        csv << curve.label << ',' << spec.parameter << ',' << curve.value << ','
            << text::format_shortest(band.wavelength) << ',' << text::format_shortest(edges[i]) << ','
            << text::format_shortest(edges[i + 1]) << ',' << text::format_number(value) << ',' << material_fields(curve)
            << '\n';
      }
      plot.series.push_back(std::move(series));
    }
  }
  close_csv(csv, csv_path);
  const Image image = draw_xy_plot(plot, font);
  write_png(image, (dir / (spec.name + ".png")).string(), {skin_metadata(spec)});
  return {image.width, image.height};
}

}  // namespace

FigureSize build_skin_figure(const FigureSpec& spec, const std::filesystem::path& dir, const Font& font, int size) {
  for (const FigureCurve& curve : spec.curves) {
    if (!curve.skin) throw std::invalid_argument("figure " + spec.name + ": curve " + curve.label + " has no skin");
  }
  if (spec.kind == FigureKind::SkinProfiles) return build_profiles(spec, dir, font, size);
  return spec.kind == FigureKind::SkinSpectra ? build_spectra(spec, dir, font, size)
                                              : build_spheres(spec, dir, font, size);
}

}  // namespace skinlayer::figures
