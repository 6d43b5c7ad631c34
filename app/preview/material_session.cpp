#include "app/preview/material_session.h"

#include <filesystem>

#include "app/preview/solve_request.h"

namespace skinlayer {

MaterialSession untitled_session(const ColorMaterial& material, std::string label) {
  MaterialSession session;
  session.label = std::move(label);
  session.saved = material;
  return session;
}

MaterialSession opened_session(const MaterialDocument& document, const std::string& path) {
  MaterialSession session;
  const bool picture = std::filesystem::path(path).extension() == ".png";
  session.path = picture ? std::string() : path;
  session.label = picture ? "from " + std::filesystem::path(path).filename().string() : std::string();
  session.name = document.name;
  session.description = document.description;
  session.saved = color_material(document);
  return session;
}

bool unsaved(const MaterialSession& session, const ColorMaterial& current) {
  return !same_request(SolveRequest{session.saved}, SolveRequest{current});
}

MaterialDocument document_to_save(const MaterialSession& session, const ColorMaterial& current) {
  MaterialDocument document = material_document(current);
  document.name = session.name;
  document.description = session.description;
  return document;
}

std::string session_name(const MaterialSession& session) {
  return session.path.empty() ? session.label : std::filesystem::path(session.path).filename().string();
}

std::string window_title(const MaterialSession& session, const ColorMaterial& current, bool unicode) {
  std::string title = (unicode ? "skinlayer \u2014 " : "skinlayer - ") + session_name(session);
  if (unsaved(session, current)) title += unicode ? " \u2022" : " *";
  return title;
}

}  // namespace skinlayer
