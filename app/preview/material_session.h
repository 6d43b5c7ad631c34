// The material file the previewer has open (or none), what was last opened or saved, and so whether there are
// unsaved changes; the window title that shows both. Plain values: the previewer owns one.
#pragma once

#include <string>

#include "app/material/material_document.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

struct MaterialSession {
  std::string path;               // the open file; empty: untitled (the defaults, a preset, or flags)
  std::string label;              // shown in the title when there is no path: "untitled", "preset wax"
  std::string name, description;  // the file's, kept when saving
  ColorMaterial saved;            // the material as opened or last saved
};

// A session for a material that came from no file (flags or defaults): nothing unsaved yet.
MaterialSession untitled_session(const ColorMaterial& material, std::string label = "untitled");

// The session after opening `document` from `path` (a material file or a PNG skinlayer wrote: saving a PNG's
// material goes to a new JSON file, so a PNG's session has no path).
MaterialSession opened_session(const MaterialDocument& document, const std::string& path);

bool unsaved(const MaterialSession& session, const ColorMaterial& current);

// The document to write for the current material: the session's name and description.
MaterialDocument document_to_save(const MaterialSession& session, const ColorMaterial& current);

// What the session is called: the file's name ("skin.json"), else its label ("untitled", "preset wax").
std::string session_name(const MaterialSession& session);

// "skinlayer — " and session_name, with " •" (or " *" without Unicode) when there are unsaved changes.
std::string window_title(const MaterialSession& session, const ColorMaterial& current, bool unicode);

}  // namespace skinlayer
