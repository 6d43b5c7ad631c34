// The presets (app/presets/*.json, embedded): each loads under its file's name with a one-line description and
// solves to a physical material; an unknown name lists the known ones.
#include "app/material/presets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

TEST(Presets, IncludeTheLooksTheIssueAsksFor) {
  std::set<std::string> names;
  for (const PresetInfo& preset : preset_list()) names.insert(preset.name);
  for (const char* wanted : {"paper-default", "paper-thin", "paper-semi-infinite", "paper-skin", "skin-fair",
                             "skin-medium", "skin-dark", "leaf", "printer-paper", "wax", "jade", "paint-red-base"}) {
    EXPECT_TRUE(names.count(wanted)) << wanted;
  }
  // Stacks (issue 12): a two-layer skin and a clear coat over a pigmented base.
  EXPECT_EQ(preset_material("skin-two-layer").layer.layer_count(), 2);
  const MaterialDocument coat = preset_material("clear-coat-red");
  EXPECT_EQ(coat.layer.layer_count(), 2);
  EXPECT_TRUE(coat.layer.has_internal_interfaces());
  EXPECT_FALSE(coat.grey());
}

TEST(Presets, EachLoadsUnderItsNameWithADescriptionAndSolves) {
  const std::vector<PresetInfo> list = preset_list();
  EXPECT_TRUE(std::is_sorted(list.begin(), list.end(),
                             [](const PresetInfo& a, const PresetInfo& b) { return a.name < b.name; }));
  for (const PresetInfo& preset : list) {
    const MaterialDocument document = preset_material(preset.name);
    EXPECT_EQ(document.name, preset.name) << "the file's \"name\" must be its file name";
    EXPECT_FALSE(preset.description.empty()) << preset.name;
    EXPECT_EQ(preset.description.find('\n'), std::string::npos) << preset.name;
    // Every channel solves; at 30 degrees it creates no energy and reflects some.
    const std::vector<Material> channels = {document.channel(0), document.channel(1), document.channel(2)};
    const std::vector<double> angle = {degrees_to_radians(30.0)};
    const std::vector<std::vector<DirectionalAlbedo>> fractions = directional_albedo(channels, angle);
    for (const std::vector<DirectionalAlbedo>& channel : fractions) {
      const DirectionalAlbedo& a = channel.front();
      EXPECT_GT(a.reflectance(), 0.0) << preset.name;
      EXPECT_GE(a.transmittance, 0.0) << preset.name;
      EXPECT_LE(a.reflectance() + a.transmittance, 1.0 + 1e-9) << preset.name;
    }
    EXPECT_NO_THROW(solve(document.layer)) << preset.name;
  }
}

TEST(Presets, AnUnknownNameListsTheKnownOnes) {
  try {
    preset_material("skin-purple");
    ADD_FAILURE() << "an unknown preset loaded";
  } catch (const MaterialFileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("skin-purple"), std::string::npos) << message;
    EXPECT_NE(message.find("skin-fair"), std::string::npos) << message;
    EXPECT_NE(message.find("wax"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace skinlayer
