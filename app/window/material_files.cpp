#include "app/window/material_files.h"

#include <exception>
#include <system_error>
#include <utility>

#include "app/material/material_file.h"
#include "app/material/presets.h"
#include "app/preview/recent_files.h"

namespace skinlayer {

MaterialFiles::MaterialFiles(MaterialSession session, std::optional<std::filesystem::path> recent_list)
    : session_(std::move(session)), recent_list_(std::move(recent_list)) {
  preset_names_ = preset_names();
  if (recent_list_) recent_ = read_recent_files(*recent_list_);
}

FileSectionInput MaterialFiles::section_input(const ColorMaterial& material) const {
  return FileSectionInput{session_name(session_), unsaved(session_, material), preset_names_, recent_, message_, 0, 0};
}

bool MaterialFiles::may_close(const ColorMaterial& material) {
  if (quit_answered_ || !unsaved(session_, material)) return true;
  dialog_ = FileDialog{FileDialog::Kind::ConfirmDiscard, "", {FileCommand::Kind::Quit, ""}};
  return false;
}

bool MaterialFiles::run(const FileCommand& command, ColorMaterial& material) {
  const bool replaces = command.kind == FileCommand::Kind::OpenPath || command.kind == FileCommand::Kind::LoadPreset;
  if (replaces && unsaved(session_, material)) {
    dialog_ = FileDialog{FileDialog::Kind::ConfirmDiscard, "", command};
    return false;
  }
  bool close = false;
  switch (command.kind) {
    case FileCommand::Kind::None:
      break;
    case FileCommand::Kind::Open:
      dialog_ = FileDialog{FileDialog::Kind::Open, chooser_start(), {}};
      break;
    case FileCommand::Kind::OpenPath:
      open(command.argument, material);
      break;
    case FileCommand::Kind::LoadPreset:
      load_preset(command.argument, material);
      break;
    case FileCommand::Kind::Save:
      if (!session_.path.empty()) {
        save(session_.path, material);
      } else if (dialog_.kind != FileDialog::Kind::ConfirmDiscard) {
        dialog_ = FileDialog{FileDialog::Kind::SaveAs, chooser_start(), {}};
      }
      // Saving in answer to the question goes on with what it interrupted (after a Save as, if it needs a path).
      if (dialog_.kind == FileDialog::Kind::ConfirmDiscard) after_answer(/*saved=*/true, material, close);
      break;
    case FileCommand::Kind::SaveAs:
      if (command.argument.empty()) {
        dialog_ = FileDialog{FileDialog::Kind::SaveAs, chooser_start(), {}};
      } else {
        save(command.argument, material);
        if (after_save_.kind != FileCommand::Kind::None && !unsaved(session_, material)) {
          close = run(std::exchange(after_save_, {}), material);
        }
      }
      break;
    case FileCommand::Kind::Discard:
      after_answer(/*saved=*/false, material, close);
      break;
    case FileCommand::Kind::Quit:
      quit_answered_ = true;
      close = true;
      break;
  }
  return close;
}

void MaterialFiles::after_answer(bool saved, ColorMaterial& material, bool& close) {
  const FileCommand next = std::exchange(dialog_, {}).after_discard;
  if (saved && unsaved(session_, material)) {
    after_save_ = next;
    dialog_ = FileDialog{FileDialog::Kind::SaveAs, chooser_start(), {}};
    return;
  }
  session_.saved = material;  // saved or discarded: what comes next no longer asks
  close = run(next, material);
}

std::string MaterialFiles::chooser_start() const {
  if (!session_.path.empty()) return session_.path;
  std::error_code error;
  const std::string folder = std::filesystem::current_path(error).string() + "/";
  return session_.name.empty() ? folder : folder + session_.name + ".json";
}

void MaterialFiles::open(const std::string& path, ColorMaterial& material) {
  try {
    const MaterialDocument document = read_material_file(path);
    material = color_material(document);
    session_ = opened_session(document, path);
    message_ = "opened " + path;
    if (!session_.path.empty()) remember(path);
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

void MaterialFiles::load_preset(const std::string& name, ColorMaterial& material) {
  try {
    const MaterialDocument document = preset_material(name);
    material = color_material(document);
    session_ = untitled_session(material, "preset " + name);
    session_.name = document.name;
    session_.description = document.description;
    message_ = document.description;
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

void MaterialFiles::save(std::string path, const ColorMaterial& material) {
  if (std::filesystem::path(path).extension().empty()) path += ".json";
  try {
    write_material_file(document_to_save(session_, material), path);
    session_.path = path;
    session_.label.clear();
    session_.saved = material;
    message_ = "saved " + path;
    remember(path);
  } catch (const std::exception& error) {
    message_ = error.what();
  }
}

void MaterialFiles::remember(const std::string& path) {
  if (!recent_list_) return;
  recent_ = with_recent_file(recent_, path);
  try {
    write_recent_files(*recent_list_, recent_);
  } catch (const std::exception&) {
    // The list is a convenience: an unwritable config folder must not stop the work.
  }
}

MaterialSession initial_session(const WindowOptions& options) {
  if (!options.material_path.empty()) {
    MaterialSession session = opened_session(options.document, options.material_path);
    session.saved = options.material;
    return session;
  }
  MaterialSession session =
      untitled_session(options.material, options.preset.empty() ? "untitled" : "preset " + options.preset);
  session.name = options.document.name;
  session.description = options.document.description;
  return session;
}

}  // namespace skinlayer
