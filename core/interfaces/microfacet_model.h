// Which light of a rough dielectric interface the model keeps: what one microfacet does to it (Stam 2001), or
// everything the microsurface does, however often light meets it (Heitz, Hanika, d'Eon & Dachsbacher 2016).
#pragma once

#include <optional>
#include <string_view>

namespace skinlayer {

enum class MicrofacetModel {
  // Stam 2001 exactly: the single-scattering BSDF with the separable Smith masking-shadowing G1(wi) G1(wo). Light
  // that one microfacet sends into another is lost, as the paper's model loses it.
  Single,
  // The light that meets the microsurface more than once kept too: the single-scattering BSDF with height-correlated
  // masking-shadowing (core/interfaces/smith_masking.h), which is what a random walk on the microsurface does in one
  // meeting, plus the multiply scattered rest.
  Multiple,
};

// "single", "multiple"; parse_microfacet_model returns nullopt for anything else.
std::string_view microfacet_model_name(MicrofacetModel model);
std::optional<MicrofacetModel> parse_microfacet_model(std::string_view name);

}  // namespace skinlayer
