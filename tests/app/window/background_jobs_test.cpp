// The previewer's background jobs (app/window/background_jobs.h): an export with nothing shown says so, a second
// export or match while one runs is refused on the panel's line, and a finished match sets its material at once,
// keeping the sphere's model. ./setup.sh test runs these under ThreadSanitizer too (ctest -L threads).
#include "app/window/background_jobs.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <thread>

#include "app/material/presets.h"

namespace skinlayer {
namespace {

using namespace std::chrono_literals;

// take_outcomes() as the window calls it each frame, until something ends (no deadline: ctest's timeout is the guard).
void wait_for_outcomes(BackgroundJobs& jobs, ColorMaterial& material, std::ostream& out) {
  while (!jobs.take_outcomes(material, out)) std::this_thread::sleep_for(1ms);
}

TEST(BackgroundJobs, AnExportWithNothingShownSaysSo) {
  BackgroundJobs jobs;
  jobs.start_export(ExportFormat::Merl, nullptr, "x.binary");
  EXPECT_EQ(jobs.last_export(), "nothing exported: no material is shown");
  EXPECT_FALSE(jobs.running());
}

TEST(BackgroundJobs, AnExportWritesTheFormatsExtensionAndReportsOnce) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("skinlayer-background-jobs-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const ColorTables tables = solve_color(ColorMaterial{});
  BackgroundJobs jobs;
  jobs.start_export(ExportFormat::Merl, &tables, (dir / "shot.png").string());
  jobs.start_export(ExportFormat::Merl, &tables, (dir / "other.png").string());  // while the first runs
  EXPECT_EQ(jobs.last_export(), "an export is already running");
  ColorMaterial material;
  std::ostringstream out;
  wait_for_outcomes(jobs, material, out);
  EXPECT_EQ(jobs.last_export().rfind("saved " + (dir / "shot.binary").string(), 0), 0u) << jobs.last_export();
  EXPECT_EQ(out.str(), jobs.last_export() + "\n");
  EXPECT_TRUE(std::filesystem::exists(dir / "shot.binary"));
  EXPECT_FALSE(std::filesystem::exists(dir / "other.binary"));
  EXPECT_FALSE(jobs.take_outcomes(material, out)) << "an outcome is taken once";
  std::filesystem::remove_all(dir);
}

TEST(BackgroundJobs, AFinishedMatchSetsItsMaterialAndKeepsTheModel) {
  ColorMaterial material = color_material(preset_material("skin-fair"));
  material.model = SubsurfaceModel::Lambert;
  const ColorMaterial before = material;
  BackgroundJobs jobs;
  jobs.start_match(material, {0.8, 0.6, 0.5});
  jobs.start_match(material, {0.8, 0.6, 0.5});  // while the first runs
  EXPECT_EQ(jobs.match_outcome(), "a match is already running");
  std::ostringstream out;
  wait_for_outcomes(jobs, material, out);
  EXPECT_EQ(out.str().rfind("match: ", 0), 0u) << out.str();
  EXPECT_EQ(out.str(), "match: " + jobs.match_outcome() + "\n");
  ASSERT_TRUE(material.skin.has_value());
  EXPECT_NE(material.skin->melanin, before.skin->melanin) << "the match set new parameters";
  EXPECT_EQ(material.model, SubsurfaceModel::Lambert) << "the sphere's model is kept";
}

}  // namespace
}  // namespace skinlayer
