// docs/model.md §21.17: the unscattered bounce's image on finer ordinates.
#include "core/spatial/unscattered_images.h"

namespace skinlayer {
namespace {

// The ordinates of the finer image.
constexpr int kFinerOrdinates = 96;

}  // namespace

UnscatteredImages::UnscatteredImages(const ProfileLayer& layer, std::span<const LateralSlab> slabs,
                                     const LateralTopInterface& entry, const LateralBottomFace& bottom,
                                     const LayerProfileOptions& options) {
  const StackDepths depths = stack_depths(slabs);
  stack_ = {depths.tau, depths.height};
  const int M = options.resolution.azimuth_modes;
  coarse_ = Operators{entry.source, entry.exit, bottom.reflection};
  const LateralTopInterface fine_entry = *entry_interface(layer, kFinerOrdinates, M, options.interface_azimuths);
  fine_ = Operators{fine_entry.source, fine_entry.exit,
                    bottom_face(layer, kFinerOrdinates, M, options.interface_azimuths)->reflection};
  const double finer = bounce(*fine_, 0.0, 1);
  scale_ = finer > 0.0 ? bounce(*coarse_, 0.0, 1) / finer : 0.0;
}

double UnscatteredImages::bounce(const Operators& o, double k, int modes) const {
  const UnscatteredLeg legs[] = {stack_, stack_};
  const std::vector<Eigen::MatrixXd>* faces[] = {&o.reflection};
  return unscattered_path_transform(o.source, legs, faces, o.exit, k, modes);
}

double UnscatteredImages::reflectance_correction(double k, int modes) const {
  if (!coarse_) return 0.0;
  return scale_ * bounce(*fine_, k, modes) - bounce(*coarse_, k, modes);
}

}  // namespace skinlayer
