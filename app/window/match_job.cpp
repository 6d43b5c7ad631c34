#include "app/window/match_job.h"

#include <cstdio>
#include <exception>
#include <utility>

#include "app/material/color_match.h"
#include "app/process/parallel_for.h"
#include "core/color/spectral_color.h"

namespace skinlayer {
namespace {

std::string srgb_text(const Eigen::Vector3d& srgb) {
  char text[64];
  std::snprintf(text, sizeof text, "sRGB %.3f, %.3f, %.3f", srgb(0), srgb(1), srgb(2));
  return text;
}

}  // namespace

bool MatchJob::start(MaterialDocument document, const Eigen::Vector3d& srgb) {
  return job_.start([document = std::move(document), srgb] {
    MatchOutcome outcome;
    try {
      const Eigen::Vector3d target(srgb_decode(srgb(0)), srgb_decode(srgb(1)), srgb_decode(srgb(2)));
      DocumentColorMatch match = match_document_color(document, target, parallel_for_threads);
      const Eigen::Vector3d reached(srgb_encode(match.reached(0)), srgb_encode(match.reached(1)),
                                    srgb_encode(match.reached(2)));
      char distance[32];
      std::snprintf(distance, sizeof distance, "CIEDE2000 %.2f", match.delta_e);
      outcome.line = match.reachable ? "matched " + srgb_text(srgb) + " (" + distance + ")"
                                     : "out of reach: " + srgb_text(srgb) + "; set the nearest, " + srgb_text(reached) +
                                           ", " + distance + " away";
      outcome.document = std::move(match.document);
    } catch (const std::exception& error) {
      outcome.line = std::string("not matched: ") + error.what();
    }
    return outcome;
  });
}

}  // namespace skinlayer
