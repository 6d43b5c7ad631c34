#include "core/interfaces/microfacet_model.h"

namespace skinlayer {

std::string_view microfacet_model_name(MicrofacetModel model) {
  return model == MicrofacetModel::Single ? "single" : "multiple";
}

std::optional<MicrofacetModel> parse_microfacet_model(std::string_view name) {
  if (name == "single") return MicrofacetModel::Single;
  if (name == "multiple") return MicrofacetModel::Multiple;
  return std::nullopt;
}

}  // namespace skinlayer
