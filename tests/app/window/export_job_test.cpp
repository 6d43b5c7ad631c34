// The previewer's export job (app/window/export_job.h): one export at a time on its own thread, its progress read
// by the window while the thread writes it, its outcome taken once, and a destructor that waits for the file.
// ./setup.sh test runs these under ThreadSanitizer too (ctest -L threads in build-tsan/).
#include "app/window/export_job.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "app/export/merl_brdf.h"

namespace skinlayer {
namespace {

using namespace std::chrono_literals;

std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("skinlayer-export-job-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

const ColorTables& solved_default() {
  static const ColorTables tables = solve_color(ColorMaterial{});  // read-only once built (a test fixture)
  return tables;
}

// Polls running(), progress() and take_outcome() as the window does each frame, until the outcome comes (without a
// deadline: an outcome that never comes runs into ctest's timeout).
std::string outcome_of(ExportJob& job, int& progress_lines) {
  while (true) {
    if (std::optional<std::string> outcome = job.take_outcome()) return *outcome;
    if (!job.progress().empty()) ++progress_lines;
    std::this_thread::sleep_for(1ms);  // a frame's pace, not a bound
  }
}

TEST(ExportJob, TheFormatsExtensionReplacesThePathsOwnOnce) {
  EXPECT_EQ(with_export_extension("out/shot.png", ExportFormat::Merl), "out/shot.binary");
  EXPECT_EQ(with_export_extension("shot.png", ExportFormat::Rgl), "shot.rgl.bsdf");
  EXPECT_EQ(with_export_extension("shot.rgl.bsdf", ExportFormat::Rgl), "shot.rgl.bsdf");
  EXPECT_EQ(with_export_extension("shot.bsdf", ExportFormat::Rgl), "shot.rgl.bsdf");
  EXPECT_EQ(with_export_extension("shot", ExportFormat::Bsdf), "shot.bsdf");
}

TEST(ExportJob, WritesTheFileOnItsThreadWhileTheOwnerReadsItsProgress) {
  const std::filesystem::path path = scratch("merl.binary");
  std::filesystem::remove(path);
  ExportJob job;
  ASSERT_TRUE(job.start(ExportFormat::Merl, solved_default(), path.string()));
  EXPECT_FALSE(job.start(ExportFormat::Merl, solved_default(), path.string())) << "one at a time";
  int progress_lines = 0;
  const std::string outcome = outcome_of(job, progress_lines);
  EXPECT_EQ(outcome, "saved " + path.string() + " (MERL, " + std::to_string(kMerlBytes) + " bytes)");
  EXPECT_EQ(std::filesystem::file_size(path), kMerlBytes);
  EXPECT_FALSE(job.running());
  EXPECT_EQ(job.progress(), "");
  EXPECT_FALSE(job.take_outcome().has_value()) << "an outcome is taken once";
  EXPECT_GT(progress_lines, 0) << "the owner saw it run";
  std::filesystem::remove(path);
}

TEST(ExportJob, AFailedExportReportsItsErrorAndWritesNothing) {
  const std::filesystem::path path = scratch("missing-folder") / "out.bsdf";
  ExportJob job;
  ASSERT_TRUE(job.start(ExportFormat::Bsdf, solved_default(), path.string()));
  int progress_lines = 0;
  const std::string outcome = outcome_of(job, progress_lines);
  EXPECT_NE(outcome.find("missing-folder"), std::string::npos) << outcome;
  EXPECT_EQ(outcome.find('\n'), std::string::npos) << "one line";
  EXPECT_FALSE(std::filesystem::exists(path));
}

// Two jobs (two windows' worth) at once, one of them restarted at once after it ends, and one destroyed while it
// runs: the destructor waits, and the file it leaves is whole.
TEST(ExportJob, JobsSideBySideAndADestructorThatWaitsForTheFile) {
  const std::filesystem::path rgl = scratch("side.rgl.bsdf"), merl = scratch("side.binary");
  const std::filesystem::path abandoned = scratch("abandoned.binary");
  std::filesystem::remove(abandoned);
  ExportJob first, second;
  ASSERT_TRUE(first.start(ExportFormat::Rgl, solved_default(), rgl.string()));
  ASSERT_TRUE(second.start(ExportFormat::Merl, solved_default(), merl.string()));
  int progress_lines = 0;
  EXPECT_EQ(outcome_of(second, progress_lines).rfind("saved ", 0), 0u);
  ASSERT_TRUE(second.start(ExportFormat::Merl, solved_default(), merl.string())) << "a finished job starts again";
  EXPECT_EQ(outcome_of(first, progress_lines).rfind("saved ", 0), 0u);
  EXPECT_EQ(outcome_of(second, progress_lines).rfind("saved ", 0), 0u);
  {
    ExportJob leaving;
    ASSERT_TRUE(leaving.start(ExportFormat::Merl, solved_default(), abandoned.string()));
  }
  EXPECT_EQ(std::filesystem::file_size(abandoned), kMerlBytes);
  std::filesystem::remove_all(rgl.parent_path());
}

}  // namespace
}  // namespace skinlayer
