#include "app/window/background_jobs.h"

#include <Eigen/Core>

namespace skinlayer {

void BackgroundJobs::start_export(ExportFormat format, const ColorTables* shown, const std::string& path) {
  if (shown == nullptr) {
    last_export_ = "nothing exported: no material is shown";
    return;
  }
  const std::string target = path.empty() ? path : with_export_extension(path, format);
  if (!export_job_.start(format, *shown, target)) last_export_ = "an export is already running";
}

void BackgroundJobs::start_match(const ColorMaterial& material, const std::array<double, 3>& srgb) {
  if (!match_job_.start(material_document(material), Eigen::Vector3d(srgb[0], srgb[1], srgb[2]))) {
    match_outcome_ = "a match is already running";
  }
}

bool BackgroundJobs::take_outcomes(ColorMaterial& material, std::ostream& out) {
  bool ended = false;
  if (const std::optional<std::string> outcome = export_job_.take_outcome()) {
    last_export_ = *outcome;
    out << *outcome << "\n" << std::flush;
    ended = true;
  }
  if (std::optional<MatchOutcome> outcome = match_job_.take_outcome()) {
    match_outcome_ = outcome->line;
    out << "match: " << outcome->line << "\n" << std::flush;
    if (outcome->document) {
      const SubsurfaceModel model = material.model;
      material = color_material(*outcome->document);
      material.model = model;
    }
    ended = true;
  }
  return ended;
}

}  // namespace skinlayer
