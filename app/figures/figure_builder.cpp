#include "app/figures/figure_builder.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/figures/model_spheres.h"
#include "app/figures/polar_plot.h"
#include "app/figures/skin_figures.h"
#include "app/material/material_flag_text.h"
#include "app/material/picture_metadata.h"
#include "app/text/numbers.h"
#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/interfaces/microfacet.h"
#include "core/solver.h"

namespace skinlayer::figures {
namespace {

struct Sample {
  double signed_theta_deg;  // < 0: back side (phi 0), >= 0: forward (phi 180)
  double f;                 // 1/sr
};

struct Lobe {
  std::string curve;  // the CSV's curve label
  std::string value;  // the varied parameter's value
  LayerParams params;
  SubsurfaceModel model;
  double theta_i_deg;
  std::vector<Sample> reflection;
  std::vector<Sample> transmission;
  double peak = 0.0;
};

constexpr int kStepDeg = 1;

double theta_of(double signed_theta_deg) { return std::abs(signed_theta_deg); }
double phi_of(double signed_theta_deg) { return signed_theta_deg < 0.0 ? 0.0 : 180.0; }

Lobe sample_lobe(const FigureCurve& curve, FigureKind kind, SolveCache& cache) {
  Lobe lobe{curve.label, curve.value, curve.params, curve.model, curve.theta_i_deg, {}, {}, 0.0};
  const Material material = curve.params.material();
  const double theta_i = degrees_to_radians(curve.theta_i_deg);
  const LayerTables* tables = kind == FigureKind::SurfaceLobes ? nullptr : &cache.tables(curve.params, curve.model);
  const RoughDielectric interface = top_interface(material);
  const Vec3 wi = direction_from_angles(theta_i, 0.0);
  for (int s = -90; s <= 90; s += kStepDeg) {
    const double theta_o = degrees_to_radians(theta_of(s)), phi = degrees_to_radians(phi_of(s));
    double r = 0.0, t = 0.0;
    if (tables == nullptr) {
      r = brdf_surface(material, theta_i, theta_o, phi);
      const Vec3 up = direction_from_angles(theta_o, phi);
      t = microfacet_btdf(interface, wi, Vec3(up.x(), up.y(), -up.z()));  // theta_o from the lower normal
    } else {
      r = tables->brdf_subsurface(theta_i, theta_o, phi);
      t = tables->btdf(theta_i, theta_o, phi);
    }
    lobe.reflection.push_back({static_cast<double>(s), r});
    lobe.transmission.push_back({static_cast<double>(s), t});
    lobe.peak = std::max({lobe.peak, r, t});
  }
  return lobe;
}

// A stack's --layer values, top to bottom, ' '-separated, ';' for ',' (figure_builder.h); empty for one layer.
std::string layers_field(const LayerParams& params) {
  if (params.below.empty()) return "";
  const Material material = params.material();
  std::string field;
  for (const StackedLayer& layer : stack_layers(material)) {
    std::string spec = format_layer_spec(layer, {layer.albedo, layer.albedo, layer.albedo});
    std::replace(spec.begin(), spec.end(), ',', ';');
    field.append(field.empty() ? "" : " ").append(spec);
  }
  return field;
}

// Commas would split a CSV field; labels never need them.
std::string csv_field(std::string text) {
  std::replace(text.begin(), text.end(), ',', ';');
  return text;
}

void write_csv(const std::vector<Lobe>& lobes, const FigureSpec& spec, const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << "curve,parameter,value,theta_i,theta_o,phi,side,quantity,f" << (spec.rescale_to_peak ? ",plotted" : "")
      << ",model,sigma,eta,T,albedo,g,layers,microfacet\n";
  for (const Lobe& lobe : lobes) {
    const std::string material =
        std::string(subsurface_model_name(lobe.model)) + "," + text::format_shortest(lobe.params.sigma) + "," +
        text::format_shortest(lobe.params.eta) + "," + text::format_shortest(lobe.params.transparency) + "," +
        text::format_shortest(lobe.params.albedo) + "," + text::format_shortest(lobe.params.g) + "," +
        layers_field(lobe.params) + "," + std::string(microfacet_model_name(lobe.params.microfacet));
    const bool surface = spec.kind == FigureKind::SurfaceLobes;
    for (const char side : {'R', 'T'}) {
      const char* quantity =
          side == 'R' ? (surface ? "brdf_surface" : "brdf_subsurface") : (surface ? "interface_btdf" : "btdf");
      for (const Sample& s : side == 'R' ? lobe.reflection : lobe.transmission) {
        out << csv_field(lobe.curve) << ',' << spec.parameter << ',' << lobe.value << ','
            << text::format_shortest(lobe.theta_i_deg) << ',' << text::format_shortest(theta_of(s.signed_theta_deg))
            << ',' << text::format_shortest(phi_of(s.signed_theta_deg)) << ',' << side << ',' << quantity << ','
            << text::format_number(s.f);
        if (spec.rescale_to_peak) out << ',' << text::format_number(lobe.peak > 0.0 ? s.f / lobe.peak : 0.0);
        out << ',' << material << '\n';
      }
    }
  }
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

std::vector<LobeSample> plotted(const std::vector<Sample>& samples, double scale) {
  std::vector<LobeSample> out;
  for (const Sample& s : samples) out.push_back({s.signed_theta_deg, s.f * scale});
  return out;
}

// The figure's metadata chunk: its first curve's material, and which parameter the other curves vary.
PngText figure_metadata(const FigureSpec& spec) {
  const FigureCurve& first = spec.curves.front();
  MaterialDocument material = grey_document(first.params.material());
  material.name = spec.name;
  material.description = spec.title + " (the first curve's material)";
  if (spec.kind == FigureKind::ModelSpheres) material.set_layer_albedo(0, first.albedo_rgb);
  material.model = first.model;
  return picture_metadata(material, figure_settings(spec));
}

}  // namespace

nlohmann::ordered_json figure_settings(const FigureSpec& spec) {
  nlohmann::ordered_json values = nlohmann::ordered_json::array();
  for (const FigureCurve& curve : spec.curves) values.push_back(curve.value);
  return {{"command", "figures"},
          {"figure", spec.name},
          {"parameter", spec.parameter},
          {"values", values},
          {"light_theta", spec.curves.front().theta_i_deg}};
}

const LayerTables& SolveCache::tables(const LayerParams& params, SubsurfaceModel model) {
  const Material material = params.material();
  for (const Entry& entry : solved_) {
    if (entry.material == material && entry.model == model) return entry.tables;
  }
  solved_.push_back({material, model, solve_model(material, model)});
  return solved_.back().tables;
}

FigureSize build_figure(const FigureSpec& spec, const std::filesystem::path& dir, const Font& font, SolveCache& cache,
                        int size) {
  if (spec.kind == FigureKind::SkinSpectra || spec.kind == FigureKind::SkinSpheres ||
      spec.kind == FigureKind::SkinProfiles) {
    return build_skin_figure(spec, dir, font, size);
  }
  std::vector<Lobe> lobes;
  if (spec.kind == FigureKind::ModelSpheres) {
    // The data behind the spheres: each model's lobes per color channel (Omega = that channel's albedo).
    constexpr std::array<const char*, 3> kChannels = {"red", "green", "blue"};
    for (const FigureCurve& curve : spec.curves) {
      for (std::size_t c = 0; c < 3; ++c) {
        FigureCurve channel = curve;
        channel.params.albedo = curve.albedo_rgb[c];
        channel.label = curve.label + " " + kChannels[c];
        lobes.push_back(sample_lobe(channel, FigureKind::SubsurfaceLobes, cache));
      }
    }
    write_csv(lobes, spec, dir / (spec.name + ".csv"));
    const Image image = draw_model_spheres(spec, font, std::max(size * 7 / 16, 64));
    write_png(image, (dir / (spec.name + ".png")).string(), {figure_metadata(spec)});
    return {image.width, image.height};
  }
  PolarPlot plot{
      spec.title,       spec.subtitle,       spec.rescale_to_peak ? "relative to each peak" : "1/sr", {}, size,
      spec.log_decades, spec.separate_scales};
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    lobes.push_back(sample_lobe(spec.curves[k], spec.kind, cache));
    const Lobe& lobe = lobes.back();
    const double scale = spec.rescale_to_peak && lobe.peak > 0.0 ? 1.0 / lobe.peak : 1.0;
    plot.curves.push_back({spec.curves[k].label, curve_color(k), lobe.theta_i_deg, plotted(lobe.reflection, scale),
                           plotted(lobe.transmission, scale)});
  }
  write_csv(lobes, spec, dir / (spec.name + ".csv"));
  const Image image = draw_polar_plot(plot, font);
  write_png(image, (dir / (spec.name + ".png")).string(), {figure_metadata(spec)});
  return {image.width, image.height};
}

}  // namespace skinlayer::figures
