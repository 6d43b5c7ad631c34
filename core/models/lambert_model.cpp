#include "core/models/lambert_model.h"

#include <vector>

#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {

double LambertModel::brdf_subsurface() const { return albedo * kInvPi; }

LambertModel lambert_model_for(const Material& material) {
  return {directional_albedo(material, std::vector<double>{0.0})[0].reflectance_subsurface};
}

}  // namespace skinlayer
