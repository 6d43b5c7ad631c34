// The previewer's work on threads of its own, beside the solve worker: the file exports (export_job.h) and "Match
// colour..." (match_job.h), with the status lines the panel shows for them. The screenshots' outcomes share the
// export's line (note_export), since the panel reports the last file written either way.
#pragma once

#include <array>
#include <optional>
#include <ostream>
#include <string>

#include "app/solution/material_solve.h"
#include "app/window/export_job.h"
#include "app/window/match_job.h"

namespace skinlayer {

class BackgroundJobs {
 public:
  // The Export buttons: `shown` (the tables on screen; null when none is) written in `format` to `path` with the
  // format's extension (a timestamped name when empty), on the export's thread.
  void start_export(ExportFormat format, const ColorTables* shown, const std::string& path);
  // "Match colour...": `material` as it is when pressed, matched to the sRGB-encoded colour on the match's thread.
  void start_match(const ColorMaterial& material, const std::array<double, 3>& srgb);

  // The outcomes of jobs that ended since the last call, each printed to `out` on a line of its own. A finished
  // match sets its parameters in `material` at once (keeping its model), so that they are one undo step. Returns
  // true if anything ended.
  bool take_outcomes(ColorMaterial& material, std::ostream& out);

  bool exporting() const { return export_job_.running(); }
  bool matching() const { return match_job_.running(); }
  bool running() const { return exporting() || matching(); }

  void note_export(std::string line) { last_export_ = std::move(line); }
  const std::string& last_export() const { return last_export_; }
  std::string export_progress() const { return export_job_.progress(); }
  const std::string& match_outcome() const { return match_outcome_; }

 private:
  ExportJob export_job_;
  MatchJob match_job_;
  std::string last_export_;    // the last export's or screenshot's outcome, for the panel
  std::string match_outcome_;  // the last match's outcome, for the Skin section
};

}  // namespace skinlayer
