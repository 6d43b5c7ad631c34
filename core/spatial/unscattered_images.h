// The image of the light that enters a finite stack as node radiance, crosses it without being scattered by the
// media, reflects once off its bottom face and leaves through the top, swapped for the same image on finer ordinates
// (docs/model.md §21.17). On the solve's nodes that light leaves as one ring per pair of nodes
// (unscattered_path_transform.h); on 96 nodes the rings are close enough for the profile's frequencies. The finer
// image is scaled to carry the solve's own power at k = 0, so that the profile still adds up to R(0).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "core/spatial/lateral_bottom_face.h"
#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"
#include "core/spatial/unscattered_path_transform.h"

namespace skinlayer {

class UnscatteredImages {
 public:
  UnscatteredImages() = default;  // none: no correction
  // `entry` and `bottom` are the solve's own operators (on options.resolution), the light entering as node radiance;
  // the slabs finite, with no interfaces between them. Builds the finer operators.
  UnscatteredImages(const ProfileLayer& layer, std::span<const LateralSlab> slabs, const LateralTopInterface& entry,
                    const LateralBottomFace& bottom, const LayerProfileOptions& options);

  // What the finer image adds to R at k on `modes` modes: its image less the solve's own.
  double reflectance_correction(double k, int modes) const;

 private:
  // One resolution's operators along the path.
  struct Operators {
    Eigen::VectorXd source, exit;
    std::vector<Eigen::MatrixXd> reflection;
  };
  double bounce(const Operators& operators, double k, int modes) const;

  UnscatteredLeg stack_;  // the whole stack, crossed down and again up
  std::optional<Operators> coarse_, fine_;
  double scale_ = 0.0;
};

}  // namespace skinlayer
