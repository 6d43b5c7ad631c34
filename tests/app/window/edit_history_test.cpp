// The previewer's undo history, open-file session and recent files (app/preview): plain values, tested without a
// window.
#include "app/preview/edit_history.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/preview/material_session.h"
#include "app/preview/recent_files.h"

namespace skinlayer {
namespace {

Edit with_sigma(double sigma) {
  Edit edit{paper_default_material(), LightState{}};
  edit.material.layer.sigma = sigma;
  return edit;
}

TEST(EditHistory, ADragIsOneStepAndUndoRedoWalkIt) {
  EditHistory history(with_sigma(0.5));
  for (double sigma = 0.5; sigma > 0.3; sigma -= 0.01) history.observe(with_sigma(sigma), true);  // dragging
  EXPECT_EQ(history.undo_steps(), 0u) << "nothing is committed while the slider is held";
  history.observe(with_sigma(0.3), false);  // released
  EXPECT_EQ(history.undo_steps(), 1u);
  Edit light = with_sigma(0.3);
  light.light.theta_degrees = 20.0;
  history.observe(light, false);
  EXPECT_EQ(history.undo_steps(), 2u);
  std::optional<Edit> back = history.undo(light);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->light.theta_degrees, 45.0);
  EXPECT_EQ(back->material.layer.sigma, 0.3);
  back = history.undo(*back);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->material.layer.sigma, 0.5);
  EXPECT_FALSE(history.undo(*back)) << "nothing before the start";
  std::optional<Edit> forward = history.redo(*back);
  ASSERT_TRUE(forward);
  EXPECT_EQ(forward->material.layer.sigma, 0.3);
  history.observe(with_sigma(0.2), false);  // a new edit after undo drops the redo branch
  EXPECT_EQ(history.redo_steps(), 0u);
  EXPECT_FALSE(history.redo(with_sigma(0.2)));
}

TEST(EditHistory, UndoDuringADragKeepsTheDraggedValueAsAStep) {
  EditHistory history(with_sigma(0.5));
  history.observe(with_sigma(0.4), true);
  const std::optional<Edit> back = history.undo(with_sigma(0.4));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->material.layer.sigma, 0.5);
  const std::optional<Edit> forward = history.redo(*back);
  ASSERT_TRUE(forward);
  EXPECT_EQ(forward->material.layer.sigma, 0.4);
}

TEST(EditHistory, IsBounded) {
  EditHistory history(with_sigma(0.05), 10);
  for (int k = 1; k <= 50; ++k) history.observe(with_sigma(0.05 + 0.01 * k), false);
  EXPECT_EQ(history.undo_steps(), 10u);
}

TEST(MaterialSession, TitleNamesTheFileAndMarksUnsavedChanges) {
  MaterialDocument document;
  document.name = "skin";
  const MaterialSession session = opened_session(document, "/tmp/looks/skin.json");
  ColorMaterial current = color_material(document);
  EXPECT_FALSE(unsaved(session, current));
  EXPECT_EQ(window_title(session, current, false), "skinlayer - skin.json");
  current.albedo_rgb[2] = 0.5;
  EXPECT_TRUE(unsaved(session, current));
  EXPECT_EQ(window_title(session, current, false), "skinlayer - skin.json *");
  EXPECT_EQ(document_to_save(session, current).name, "skin");
  EXPECT_EQ(document_to_save(session, current).albedo_rgb[2], 0.5);
  const MaterialSession picture = opened_session(document, "shot.png");
  EXPECT_TRUE(picture.path.empty()) << "a picture's material is saved to a new file";
  EXPECT_EQ(window_title(picture, color_material(document), false), "skinlayer - from shot.png");
}

TEST(RecentFiles, NewestFirstWithoutDuplicatesAndBounded) {
  std::vector<std::string> list;
  for (int k = 0; k < 15; ++k) list = with_recent_file(list, "/tmp/m" + std::to_string(k) + ".json");
  list = with_recent_file(list, "/tmp/m12.json");
  ASSERT_EQ(list.size(), kMaxRecentFiles);
  EXPECT_EQ(list[0], "/tmp/m12.json");
  EXPECT_EQ(list[1], "/tmp/m14.json");
  EXPECT_EQ(std::count(list.begin(), list.end(), "/tmp/m12.json"), 1);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("skinlayer-recent-" + std::to_string(::getpid())) / "recent.json";
  write_recent_files(file, list);
  EXPECT_EQ(read_recent_files(file), list);
  std::ofstream(file) << "{ not json";
  EXPECT_TRUE(read_recent_files(file).empty()) << "a damaged list is ignored";
  std::filesystem::remove_all(file.parent_path());
}

TEST(RecentFiles, LiveInTheXdgConfigFolder) {
  const char* home = std::getenv("HOME");
  const std::string saved_home = home != nullptr ? home : "";
  ::setenv("XDG_CONFIG_HOME", "/tmp/xdg-test", 1);
  EXPECT_EQ(recent_files_path(), std::filesystem::path("/tmp/xdg-test/skinlayer/recent.json"));
  ::unsetenv("XDG_CONFIG_HOME");
  ::setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(recent_files_path(), std::filesystem::path("/home/someone/.config/skinlayer/recent.json"));
  if (home != nullptr) ::setenv("HOME", saved_home.c_str(), 1);
}

}  // namespace
}  // namespace skinlayer
