#include "app/solution/document_profile.h"

#include <algorithm>
#include <cmath>

#include "app/material/color_channels.h"
#include "app/text/numbers.h"
#include "core/spatial/layer_profile.h"

namespace skinlayer {
namespace {

// One line naming what the profile cannot take yet, or nothing for a material it can: layers each with their
// extinction when there are several, interfaces between them only under a rough top or in diffuse light
// and in a stack that ends in a half-space, and a rough bottom or a Lambertian base only where the light enters
// spread over directions (a rough top, or diffuse light).
void require_profile_layer(const Material& m, Incidence incidence) {
  std::string why;
  const bool stack = m.layer_count() > 1;
  const bool ends_in_half_space = std::isinf(m.total_tau());
  const bool all_lengths = m.extinction && std::all_of(m.below.begin(), m.below.end(),
                                                       [](const StackedLayer& l) { return l.extinction.has_value(); });
  const bool faces = m.has_internal_interfaces();
  const bool collimated = m.eta == 1.0 && incidence == Incidence::Normal;
  const bool bottom_face = !ends_in_half_space && (m.bottom.kind == BottomKind::Lambert ||
                                                   (m.bottom.kind == BottomKind::Air && m.bottom_eta() != 1.0));
  if (faces && collimated) {
    why =
        "it has an interface between its layers under no top interface (--eta 1), which the beam reaches "
        "unscattered";
  } else if (faces && !ends_in_half_space) {
    why = "it has an interface between its layers over a finite stack (its last layer needs tau=inf)";
  } else if (stack && !all_lengths) {
    // Not a geometry the profile lacks, but a number the material lacks: said alone, with what to give.
    throw ParameterError(
        "profile: the stack's layers do not all have their extinction (mu_t=, 1/mm), which relates their lengths "
        "across the stack; give every layer one (--layer ...,mu_t=MU_T)");
  } else if (bottom_face && collimated) {
    why = m.bottom.kind == BottomKind::Lambert
              ? "it has a Lambertian base (--bottom " + format_bottom(m.bottom) +
                    ") under no top interface (--eta 1), which the beam reaches unscattered"
              : "it has a rough bottom interface (bottom-eta " + text::format_shortest(m.bottom_eta()) +
                    ") under no top interface (--eta 1), which the beam reaches unscattered";
  }
  if (why.empty()) return;
  throw ParameterError(
      "profile: spatial profiles are computed so far with interfaces between layers only under a rough top over a "
      "half-space, and a rough bottom or a Lambertian base only under a rough top or in diffuse light; this "
      "material cannot be: " +
      why);
}

// Light that enters as radiance spread over directions (through a rough top, or diffuse) and leaves a finite stack's
// bottom carries the ordinates' ray effect: each node's stream makes a ring. 12 nodes leave the transmittance of a
// slab of tau 1 under a sigma 0.3 top up to 4.7% off the walk in some annuli, 24 within 1%
// (tests/core/spatial/finite_stack_transmittance_test.cpp), so the transmittance is computed on 24 nodes at least.
constexpr int kTransmittedRadianceOrdinates = 24;

LayerProfileOptions options_for(const Material& m, const ProfileRequest& request) {
  LayerProfileOptions options = request.options;
  const bool finite = std::isfinite(m.total_tau());
  if (finite && !options.reflectance_only && (m.eta != 1.0 || request.incidence == Incidence::Diffuse)) {
    options.resolution.ordinates = std::max(options.resolution.ordinates, kTransmittedRadianceOrdinates);
  }
  return options;
}

// The document's distinct solves and how they make the red, green and blue channels (a grey document: one solve;
// a skin: its wavelengths).
ColorChannels profile_solves(const MaterialDocument& document, const ProfileRequest& request) {
  ColorChannels solves = color_channels(document, request.preview);
  for (const Material& material : solves.materials) require_profile_layer(material, request.incidence);
  return solves;
}

template <class Profile>
DocumentProfile document_profile(const MaterialDocument& document, const ProfileRequest& request,
                                 std::span<const double> positions, const Profile& profile) {
  const ColorChannels solves = profile_solves(document, request);
  const bool in_mm = solves.materials.front().extinction.has_value();
  // Each solve in its own first layer's mean free paths (a skin's extinction changes with the wavelength), then back
  // to the document's unit: mm with the extinction mu_t (1/mm), or mfp (mu_t = 1).
  std::vector<LayerProfile> per_solve;
  std::vector<double> mu_t;
  for (const Material& material : solves.materials) {
    mu_t.push_back(material.extinction.value_or(1.0));
    std::vector<double> in_mfp;
    for (const double r : positions) in_mfp.push_back(r * mu_t.back());
    per_solve.push_back(profile(material, in_mfp));
    if (request.progress) {
      request.progress(static_cast<int>(per_solve.size()), static_cast<int>(solves.materials.size()));
    }
  }
  DocumentProfile result;
  result.unit = in_mm ? "mm" : "mfp";
  // Channel c = sum_k to_rgb(c, k) solve k (an RGB document's channels each pick one of its distinct solves).
  const int channels = document.grey() ? 1 : 3;
  for (int c = 0; c < channels; ++c) {
    std::vector<double> reflectance(per_solve.front().reflectance.size(), 0.0);
    std::vector<double> transmittance(reflectance.size(), 0.0);
    for (std::size_t k = 0; k < per_solve.size(); ++k) {
      const double weight = mu_t[k] * mu_t[k] * solves.to_rgb(c, static_cast<Eigen::Index>(k));  // 1/mfp^2 -> 1/unit^2
      for (std::size_t i = 0; i < reflectance.size(); ++i) {
        reflectance[i] += weight * per_solve[k].reflectance[i];
        if (!per_solve[k].transmittance.empty()) transmittance[i] += weight * per_solve[k].transmittance[i];
      }
    }
    result.reflectance.push_back(std::move(reflectance));
    if (!request.options.reflectance_only) result.transmittance.push_back(std::move(transmittance));
  }
  return result;
}

}  // namespace

// The command's resolution: tests/core/spatial/layer_profile_test.cpp checks it against the walk and MCML (within
// 2.6% or 3 standard errors wherever the profile exceeds 1e-3 of its peak).
LayerProfileOptions document_profile_options() {
  LayerProfileOptions options;
  options.resolution = {12, 16};
  options.frequencies = 40;
  return options;
}

DocumentProfile document_profile_in_annuli(const MaterialDocument& document, std::span<const double> edges,
                                           const ProfileRequest& request) {
  return document_profile(document, request, edges, [&](const Material& m, std::span<const double> edges_mfp) {
    return layer_profile(profile_layer(m, request.incidence), edges_mfp, options_for(m, request));
  });
}

DocumentProfile document_profile_at_radii(const MaterialDocument& document, std::span<const double> radii,
                                          const ProfileRequest& request) {
  return document_profile(document, request, radii, [&](const Material& m, std::span<const double> radii_mfp) {
    return layer_profile_at(profile_layer(m, request.incidence), radii_mfp, options_for(m, request));
  });
}

}  // namespace skinlayer
