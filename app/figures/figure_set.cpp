#include "app/figures/figure_set.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <initializer_list>

namespace skinlayer::figures {
namespace {

std::string shortest(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

// One curve per value of a parameter: set(params, theta_i, value) applies it to a copy of the base.
template <typename Setter>
std::vector<FigureCurve> vary(const std::string& symbol, std::initializer_list<double> values, const LayerParams& base,
                              Setter set, const std::string& unit = "") {
  std::vector<FigureCurve> curves;
  for (double value : values) {
    FigureCurve curve{"", "", base};  // constructed, not assigned: GCC 12 warns falsely (-Wnonnull) on the latter
    set(curve, value);
    curve.value = shortest(value);
    curve.label = symbol + " = " + curve.value + unit;
    curves.push_back(curve);
  }
  return curves;
}

FigureSpec subsurface(std::string name, std::string title, std::string subtitle, std::string parameter,
                      std::vector<FigureCurve> curves, std::string what_it_shows) {
  FigureSpec spec;
  spec.name = std::move(name);
  spec.title = std::move(title);
  spec.subtitle = subtitle;
  spec.parameter = std::move(parameter);
  spec.kind = FigureKind::SubsurfaceLobes;
  spec.separate_scales = true;  // the transmitted lobes reach several times the reflected ones
  spec.curves = std::move(curves);
  spec.caption = "Subsurface lobes (Stam's model with his single-scattering interfaces, --microfacet single; "
                 "subsurface part only: brdf_subsurface above the surface line, "
                 "the layer's btdf below), in the plane of incidence, sampled every 1°; reflection and transmission have separate radial scales. " +
                 what_it_shows + " Fixed: " + subtitle + "; bottom air.";
  return spec;
}

}  // namespace

Material LayerParams::material() const {
  Material m;
  m.sigma = sigma;
  m.eta = eta;
  m.tau = optical_depth_from_transparency(transparency);
  m.albedo = albedo;
  m.g = g;
  m.below = below;
  m.microfacet = microfacet;
  return m;
}

namespace {

// The spectral skin (issue 25): spectra against melanin and against blood at the integrating sphere's 8 degrees, and
// a row of spheres across the pigmentation ranges, all under the skin presets' top (sigma 0.35, eta 1.4); every
// other skin parameter at its default.
// A fraction as a label: 0.035 -> "3.5%".
std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%g%%", 100.0 * fraction);
  return text;
}

void append_skin_figures(std::vector<FigureSpec>& set) {
  LayerParams top;
  top.sigma = 0.35;
  top.microfacet = MicrofacetModel::Multiple;  // skinlayer's own figures: the default interfaces, as `spectrum`'s
  const auto skin_curve = [&](const std::string& key, double value, const std::string& label) {
    FigureCurve curve{label, shortest(value), top};
    curve.theta_i_deg = 8.0;
    curve.skin = SkinParameters{};
    skin_parameter(*curve.skin, key) = value;
    return curve;
  };
  FigureSpec melanin;
  melanin.name = "skin-spectra-melanin";
  melanin.title = "Skin reflectance at 8° against epidermal melanin (blood 0.5%)";
  melanin.subtitle = "blood 0.5% · oxygenation 75% · epidermis 0.06 mm · σ 0.35 · η 1.4 · θi 8°";
  melanin.parameter = "melanin";
  melanin.kind = FigureKind::SkinSpectra;
  for (const double m : {0.01, 0.035, 0.135, 0.30, 0.43}) {
    melanin.curves.push_back(skin_curve("melanin", m, "melanin " + percent(m)));
  }
  melanin.caption = "The spectral skin's directional-hemispherical reflectance at 8° (surface and subsurface, "
                    "energy-conserving interfaces, --microfacet multiple) from "
                    "400 to 700 nm as the epidermal melanin fraction rises from 1% to 43%, across Jacques' (1998) "
                    "ranges for light (1.3-6.3%), moderately (11-16%) and darkly (18-43%) pigmented adults. Melanin "
                    "absorbs most at short wavelengths, so it lowers blue more than red; hemoglobin's dips at 542 "
                    "and 577 nm fade as less light reaches the dermis.";
  set.push_back(melanin);

  FigureSpec blood;
  blood.name = "skin-spectra-blood";
  blood.title = "Skin reflectance at 8° against dermal blood (melanin 3.5%)";
  blood.subtitle = "melanin 3.5% · oxygenation 75% · epidermis 0.06 mm · σ 0.35 · η 1.4 · θi 8°";
  blood.parameter = "blood";
  blood.kind = FigureKind::SkinSpectra;
  for (const double b : {0.002, 0.005, 0.02, 0.05, 0.1}) {
    FigureCurve curve = skin_curve("blood", b, "blood " + percent(b));
    curve.skin->melanin = 0.035;
    blood.curves.push_back(curve);
  }
  blood.caption =
      "The same at melanin 3.5% (light skin in Jacques' ranges) as the dermal blood volume fraction rises from "
      "0.2% to 10%: the oxy- and deoxyhemoglobin bands (the W between 540 and 580 nm, and the Soret "
      "band below 450 nm) deepen, and the rise past 600 nm, where hemoglobin hardly absorbs, stays.";
  set.push_back(blood);

  FigureSpec spheres;
  spheres.name = "skin-spheres";
  spheres.title = "Skin from chromophores: melanin 1% to 43%";
  spheres.subtitle = "blood 0.5% · σ 0.35 · η 1.4 · linear sRGB under D65 · light 45° from the left";
  spheres.parameter = "melanin";
  spheres.kind = FigureKind::SkinSpheres;
  for (const double m : {0.01, 0.035, 0.135, 0.30, 0.43}) {
    FigureCurve curve = skin_curve("melanin", m, "melanin " + percent(m));
    curve.theta_i_deg = 45.0;
    spheres.curves.push_back(curve);
  }
  spheres.caption =
      "Spheres of the spectral skin across the pigmentation ranges that Jacques (1998) gives for "
      "light, moderately and darkly pigmented adults, each solved at 31 wavelengths and shown in "
      "linear sRGB under D65 with skinlayer render's renderer. The CSV holds each skin's colour at "
      "normal incidence (the sphere's centre under a white furnace), which `skinlayer albedo --skin` "
      "reproduces.";
  set.push_back(spheres);

  // Light that travels under the skin (issue 43): fair, medium and dark skins' profiles, and the same skins side-lit
  // on a sphere the size of a fingertip, where it bleeds past the terminator.
  const std::array<std::pair<double, const char*>, 3> tones = {std::pair{0.03, "fair"}, std::pair{0.135, "medium"},
                                                               std::pair{0.30, "dark"}};
  FigureSpec profiles;
  profiles.name = "skin-profiles";
  profiles.title = "Where light leaves skin: reflectance profiles at 650, 550 and 450 nm";
  profiles.subtitle = "melanin 3%, 13.5%, 30% · blood 0.5% · σ 0.35 · η 1.4 · normal incidence";
  profiles.parameter = "melanin";
  profiles.kind = FigureKind::SkinProfiles;
  for (const auto& [m, tone] : tones) profiles.curves.push_back(skin_curve("melanin", m, tone));
  profiles.caption =
      "The spectral skin's reflectance profile R(r), the light of a pencil beam at normal incidence leaving per "
      "mm² at r mm from it (the top's own reflection left out), averaged over 0.2 mm annuli: log10 R + 4 at "
      "650, 550 and 450 nm for fair, medium and dark skin (skinlayer profile --skin ... --wavelength W "
      "--annuli 0.2:20). Red light travels millimetres; green and blue are absorbed sooner, more so under more "
      "melanin.";
  set.push_back(profiles);

  FigureSpec bleeding = spheres;
  bleeding.name = "skin-spheres-translucent";
  bleeding.title = "Side-lit skin bleeds red past the terminator";
  bleeding.subtitle = "a 10 mm sphere · light 85° from the left · blood 0.5% · σ 0.35 · η 1.4";
  bleeding.light_theta_deg = 85.0;
  bleeding.sphere_radius_mm = 10.0;
  bleeding.curves.clear();
  for (const auto& [m, tone] : tones) bleeding.curves.push_back(skin_curve("melanin", m, tone));
  bleeding.caption =
      "The same three skins on a sphere of radius 10 mm lit from the side (skinlayer render --sphere-radius 10): "
      "the subsurface light spreads over the sphere by each skin's profile, pre-integrated over its curvature, "
      "and reaches past the terminator, red where melanin lets it through.";
  set.push_back(bleeding);
}

}  // namespace

std::vector<FigureSpec> figure_set() {
  std::vector<FigureSpec> set;
  const LayerParams paper;  // σ 0.5, η 1.4, T 0.2, Ω 1, g 0.8

  FigureSpec surface;
  surface.name = "surface-lobes";
  surface.title = "Surface BRDF and BTDF";
  surface.subtitle = "σ 0.5 · η 1.4 · θi 45°";
  surface.parameter = "sigma";
  surface.kind = FigureKind::SurfaceLobes;
  surface.curves = vary("σ", {0.5}, paper, [](FigureCurve& c, double v) { c.params.sigma = v; });
  surface.curves.front().label = "rough dielectric interface: σ 0.5 · η 1.4";
  surface.separate_scales = true;  // the BTDF into the layer peaks ~50 times higher than the BRDF
  surface.caption = "The top interface alone (Beckmann microfacets, exact Fresnel, Smith shadowing; one microfacet "
                    "meeting, as in Stam 2001, --microfacet single): its BRDF "
                    "(brdf_surface) above the surface line and its radiance BTDF into the layer below, at σ 0.5, "
                    "η 1.4, θi 45°. Reflection and transmission have separate radial scales (the BTDF peaks about "
                    "50 times higher).";
  set.push_back(surface);

  FigureSpec sigma = surface;
  sigma.name = "surface-sigma";
  sigma.title = "Surface lobes, varying roughness σ";
  sigma.subtitle = "η 1.4 · θi 45°";
  sigma.curves = vary("σ", {0.1, 0.2, 0.3, 0.5, 0.9}, paper, [](FigureCurve& c, double v) { c.params.sigma = v; });
  sigma.log_decades = 3;
  sigma.caption = "The top interface's BRDF (above) and radiance BTDF into the layer (below) for σ ∈ {0.1, 0.2, 0.3, "
                  "0.5, 0.9}, at η 1.4, θi 45°, with one microfacet meeting (--microfacet single). The radius is log10 of the value over 3 decades, with separate scales "
                  "for reflection and transmission: the smooth interfaces' peaks are orders of magnitude above the "
                  "rough ones'.";
  set.push_back(sigma);

  FigureSpec eta = surface;
  eta.name = "surface-eta";
  eta.title = "Surface lobes, varying index η";
  eta.subtitle = "σ 0.5 · θi 45°";
  eta.parameter = "eta";
  eta.curves = vary("η", {1.2, 1.4, 1.6, 2.0}, paper, [](FigureCurve& c, double v) { c.params.eta = v; });
  eta.log_decades = 0;
  eta.caption = "The top interface's BRDF (above) and radiance BTDF into the layer (below) for η ∈ {1.2, 1.4, 1.6, "
                "2.0}, at σ 0.5, θi 45°, with one microfacet meeting (--microfacet single). Reflection and "
                "transmission have separate radial scales.";
  set.push_back(eta);

  set.push_back(subsurface("subsurface-theta0", "Subsurface lobes, varying incident angle θ0",
                           "g 0.8 · T 0.2 · Ω 1 · σ 0.5 · η 1.4", "theta_i",
                           vary("θ0", {85, 60, 45, 30, 0}, paper,
                                [](FigureCurve& c, double v) { c.theta_i_deg = v; }, "°"),
                           "The incident angle θ0 ∈ {85°, 60°, 45°, 30°, 0°} varies."));
  set.push_back(subsurface("subsurface-g", "Subsurface lobes, varying asymmetry g",
                           "T 0.2 · Ω 1 · σ 0.5 · η 1.4 · θi 45°", "g",
                           vary("g", {0, 0.2, 0.4, 0.6, 0.8}, paper, [](FigureCurve& c, double v) { c.params.g = v; }),
                           "The Henyey-Greenstein asymmetry g ∈ {0, 0.2, 0.4, 0.6, 0.8} varies."));
  LayerParams thin = paper;
  thin.transparency = 0.1;
  set.push_back(subsurface("subsurface-sigma", "Subsurface lobes, varying roughness σ",
                           "g 0.8 · T 0.1 · Ω 1 · η 1.4 · θi 45°", "sigma",
                           vary("σ", {0.1, 0.2, 0.3, 0.5, 0.9}, thin,
                                [](FigureCurve& c, double v) { c.params.sigma = v; }),
                           "The interfaces' roughness σ ∈ {0.1, 0.2, 0.3, 0.5, 0.9} varies (top and bottom)."));
  set.push_back(subsurface("subsurface-albedo", "Subsurface lobes, varying albedo Ω",
                           "g 0.8 · T 0.2 · σ 0.5 · η 1.4 · θi 45°", "albedo",
                           vary("Ω", {0.1, 0.5, 1.0}, paper, [](FigureCurve& c, double v) { c.params.albedo = v; }),
                           "The single-scattering albedo Ω ∈ {0.1, 0.5, 1} varies."));
  set.push_back(subsurface("subsurface-T", "Subsurface lobes, varying transparency T",
                           "g 0.8 · Ω 1 · σ 0.5 · η 1.4 · θi 45°", "T",
                           vary("T", {0, 0.05, 0.1, 0.3, 0.9}, paper,
                                [](FigureCurve& c, double v) { c.params.transparency = v; }),
                           "The transparency T = exp(−τb) ∈ {0, 0.05, 0.1, 0.3, 0.9} varies (T 0: semi-infinite)."));
  LayerParams deep = paper;
  deep.transparency = 0.0;
  FigureSpec shapes = subsurface("subsurface-albedo-shape", "Lobe shapes, varying albedo Ω (each rescaled to 1)",
                                 "g 0.8 · T 0 · σ 0.5 · η 1.4 · θi 45°", "albedo",
                                 vary("Ω", {0.1, 0.5, 1.0}, deep,
                                      [](FigureCurve& c, double v) { c.params.albedo = v; }),
                                 "A semi-infinite layer (T 0, so nothing is transmitted) with Ω ∈ {0.1, 0.5, 1}; each "
                                 "curve is divided by its own peak so the shapes can be compared (the CSV's f is the "
                                 "value before rescaling, plotted the value drawn).");
  shapes.rescale_to_peak = true;
  set.push_back(shapes);

  // Stacks (issue 12): a two-layer skin against each of its layers alone.
  LayerParams epidermis = paper;
  epidermis.sigma = 0.35;
  epidermis.transparency = 0.5;
  epidermis.albedo = 0.9;
  epidermis.g = 0.8;
  const StackedLayer dermis_layer{INFINITY, 0.99, 0.3, std::nullopt};
  LayerParams two_layers = epidermis;
  two_layers.below = {dermis_layer};
  LayerParams dermis = epidermis;
  dermis.transparency = 0.0;
  dermis.albedo = dermis_layer.albedo;
  dermis.g = dermis_layer.g;
  FigureSpec stack = subsurface(
      "stack-skin", "A two-layer skin against each layer alone", "σ 0.35 · η 1.4 · θi 45°", "layers",
      {FigureCurve{"epidermis over dermis", "stack", two_layers},
       FigureCurve{"epidermis alone: T 0.5, Ω 0.9, g 0.8", "epidermis", epidermis},
       FigureCurve{"dermis alone: semi-infinite, Ω 0.99, g 0.3", "dermis", dermis}},
      "A thin, forward-scattering, absorbing epidermis (T 0.5, Ω 0.9, g 0.8) over a semi-infinite, nearly white, "
      "less forward dermis (Ω 0.99, g 0.3), against each alone under the same top. The stack's subsurface "
      "reflectance at 45° (0.37) lies between the epidermis's (0.09: it transmits most light to the air below it) "
      "and the dermis's (0.51: the epidermis absorbs on the way in and out), and its lobe keeps the dermis's broad "
      "shape, without the epidermis's forward-grazing peak. The stack and the dermis transmit nothing.");
  set.push_back(stack);

  FigureSpec spheres;
  spheres.name = "model-spheres";
  spheres.title = "Lambert | Hanrahan-Krueger | Stam";
  spheres.subtitle = "σ 0.35 · η 1.4 · T 0.05 · g 0.8 · Ω (0.95, 0.7, 0.55) · light 45° from the left";
  spheres.parameter = "model";
  spheres.kind = FigureKind::ModelSpheres;
  LayerParams skin;
  skin.sigma = 0.35;
  skin.transparency = 0.05;
  for (SubsurfaceModel model : {SubsurfaceModel::Lambert, SubsurfaceModel::HanrahanKrueger, SubsurfaceModel::Stam}) {
    FigureCurve curve{"", "", skin};
    curve.model = model;
    curve.value = std::string(subsurface_model_name(model));
    curve.label = model == SubsurfaceModel::Lambert           ? "Lambert"
                  : model == SubsurfaceModel::HanrahanKrueger ? "Hanrahan-Krueger"
                                                              : "Stam (new model)";
    curve.albedo_rgb = {0.95, 0.7, 0.55};
    spheres.curves.push_back(curve);
  }
  spheres.caption = "The three subsurface models on a sphere under one directional light 45° from the view "
                    "direction, at skin-like settings: σ 0.35, η 1.4, T 0.05, g 0.8, Ω (0.95, 0.7, 0.55) per RGB "
                    "channel; the same surface term on each, single-scattering interfaces as in the paper. Rendered with skinlayer render's OSMesa renderer. The "
                    "CSV holds each model's subsurface BRDF per channel in the plane of incidence at θi 45°.";
  set.push_back(spheres);
  append_skin_figures(set);
  return set;
}

}  // namespace skinlayer::figures
