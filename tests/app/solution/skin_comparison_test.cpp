// The comparison models of a skin (app/solution/skin_comparison.h): the one RGB layer that stands for it reflects
// what the skin reflects at normal incidence in every channel, so the Lambert model's albedo is the skin's own; the
// colour solve and eval give the same comparison model; and the compare view renders a skin's three spheres.
#include "app/solution/skin_comparison.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/material/color_channels.h"
#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"
#include "core/skin/skin_optics.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

SolveOptions threaded() {
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  return options;
}

// The skin's reflectance at normal incidence per channel, computed here from its layers at each wavelength.
std::array<double, 3> skin_reflectance(const MaterialDocument& document) {
  const ColorChannels spectrum = color_channels(document);
  std::vector<DirectionalAlbedo> rows;
  for (const Material& m : spectrum.materials) {
    rows.push_back(directional_albedo(m, std::vector<double>{0.0}, threaded()).front());
  }
  std::array<double, 3> rgb{};
  for (int c = 0; c < 3; ++c) rgb[c] = mixed_albedo(rows, spectrum.to_rgb.row(c)).reflectance();
  return rgb;
}

TEST(SkinComparison, TheLayerReflectsWhatTheSkinReflectsAtNormalIncidence) {
  for (const std::string name : {"skin-fair", "skin-medium", "skin-dark"}) {
    const MaterialDocument document = preset_material(name);
    const SkinComparisonLayer comparison = skin_comparison_layer(color_material(document), threaded());
    const std::array<double, 3> skin = skin_reflectance(document);
    const Material& top = comparison.layer.layer;
    EXPECT_EQ(top.sigma, document.layer.sigma) << name;
    EXPECT_EQ(top.eta, document.layer.eta) << name;
    EXPECT_TRUE(std::isinf(top.tau)) << name << ": semi-infinite";
    EXPECT_EQ(top.g, kSkinAnisotropy) << name;
    EXPECT_TRUE(top.below.empty()) << name << ": one layer";
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(comparison.reflectance[c], skin[c], 1e-12) << name << " channel " << c;
      Material channel = top;
      channel.albedo = comparison.layer.albedo_rgb[c];
      const double layer = directional_albedo(channel, std::vector<double>{0.0}, threaded()).front().reflectance();
      EXPECT_NEAR(layer, skin[c], 1e-6) << name << " channel " << c;  // the bisection's tolerance
    }
    EXPECT_GT(comparison.layer.albedo_rgb[0], comparison.layer.albedo_rgb[2]) << name << ": skin is red";
  }
}

// Lambert's albedo is the layer's subsurface reflectance at the normal, which is the skin's: the two share the
// surface term. Both the colour solve and eval's solve of a skin under a comparison model take that layer.
TEST(SkinComparison, TheColourSolveAndEvalTakeTheLayerForEachComparisonModel) {
  const MaterialDocument document = preset_material("skin-medium");
  const std::array<double, 3> skin = skin_reflectance(document);
  ColorMaterial material = color_material(document);
  const Material top = skin_comparison_layer(material, threaded()).layer.layer;  // the skin's top interface
  const double surface = directional_albedo(top, std::vector<double>{0.0}).front().reflectance_surface;
  for (const SubsurfaceModel model : {SubsurfaceModel::Lambert, SubsurfaceModel::HanrahanKrueger}) {
    material.model = model;
    const ColorTables tables = solve_color(material, 0.0, threaded());
    const SolvedDocument solved = solve_document(document, model, parallel_for_threads);
    EXPECT_EQ(solved.model, model);
    for (const double theta_o : {0.0, 30.0, 60.0}) {
      const BsdfPoint point = evaluate(solved, 0.0, degrees_to_radians(theta_o), kPi);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(tables.channels[c].brdf_subsurface(0.0, degrees_to_radians(theta_o), kPi), point.subsurface[c],
                    1e-12 + 1e-9 * point.subsurface[c])
            << subsurface_model_name(model) << " channel " << c << " theta_o " << theta_o;
      }
    }
    if (model == SubsurfaceModel::Lambert) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(tables.channels[c].brdf_subsurface(0.0, 0.0, 0.0) * kPi + surface, skin[c], 1e-6) << c;
      }
    }
  }
}

}  // namespace
}  // namespace skinlayer
