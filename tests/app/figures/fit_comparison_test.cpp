// The fit's picture (app/figures/fit_comparison.h): with the material itself as the "fitted" BSDF the two spheres
// are the same pixels and the map is white, its RMS 0; a BSDF 10% brighter everywhere is 10% off in every lit pixel.
// So the map shows the fit's difference and nothing of its own.
#include "app/figures/fit_comparison.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"

namespace skinlayer::figures {
namespace {

FittedBrdf material_itself(const SolvedDocument& solved, double scale) {
  return [&solved, scale](const Vec3& i, const Vec3& o) {
    const double phi = radians_to_degrees(std::atan2(o.y(), o.x()) - std::atan2(i.y(), i.x()));
    const BsdfPoint point =
        evaluate(solved, std::acos(std::min(1.0, i.z())), std::acos(std::min(1.0, o.z())), degrees_to_radians(phi));
    Eigen::Array3d value;
    for (int c = 0; c < 3; ++c)
      value(c) = scale * (point.surface + point.subsurface[static_cast<std::size_t>(c)]) * i.z();
    return value;
  };
}

TEST(FitComparison, TheMaterialAgainstItselfIsAWhiteMap) {
  const MaterialDocument wax = preset_material("wax");
  const SolvedDocument solved = solve_document(wax, SubsurfaceModel::Stam, parallel_for_threads);
  const Font font;
  const FitComparison same =
      draw_fit_comparison(wax, material_itself(solved, 1.0), "itself", font, 64, parallel_for_threads);
  EXPECT_GT(same.lit_pixels, 1000);
  EXPECT_LT(same.rms_difference, 1e-6);
  const FitComparison brighter =
      draw_fit_comparison(wax, material_itself(solved, 1.1), "brighter", font, 64, parallel_for_threads);
  EXPECT_NEAR(brighter.rms_difference, 0.1, 1e-6);
  EXPECT_EQ(same.image.width, 3 * 64);
}

}  // namespace
}  // namespace skinlayer::figures
