// glTF 2.0's metallic-roughness material (Khronos, glTF 2.0 specification, Appendix B "BRDF Implementation") with the
// KHR extensions a fitted opaque dielectric needs: the target whose parameters `skinlayer fit --target gltf` chooses,
// for three.js, Godot and the engines' glTF importers. As the texts write it, with
// w = (1 - |omega_o.h|)^5 (Schlick's weight, at the half vector):
//   specular_brdf   D V: GGX's D of alpha = roughness^2 and the height-correlated Smith visibility
//                   V = G2 / (4 mu_i mu_o) (Appendix B "Specular BRDF"), 1/sr, not Fresnel-weighted;
//   diffuse_brdf    base_color / pi (Lambert; "Diffuse BRDF");
//   dielectric      KHR_materials_ior and KHR_materials_specular ("Implementation"): F0 = min(((ior - 1) /
//                   (ior + 1))^2 specular_color, 1) specular, F90 = specular, F = F0 + (F90 - F0) w (RGB),
//                   dielectric = F specular_brdf + (1 - max(F)) diffuse_brdf; with no extension F0 = 0.04, F90 = 1;
//   metal           (base_color + (1 - base_color) w) specular_brdf ("Metal BRDF and Dielectric BRDF");
//   material        lerp(dielectric, metal, metallic);
//   sheen           KHR_materials_sheen ("Sheen layering", albedo scaling): sheen_color f_sheen + material S,
//                   S = min(1 - max(sheen_color) E(mu_o), 1 - max(sheen_color) E(mu_i)), with the lobe and E as
//                   three.js has them (charlie_sheen.h);
//   clearcoat       KHR_materials_clearcoat ("Layering"): lerp(sheened, coat_brdf, clearcoat Fc(mu_o)), the coat a
//                   specular_brdf of alpha = clearcoat_roughness^2 and Fc = 0.04 + 0.96 (1 - mu_o)^5: at the
//                   normal, not the half vector, and of index 1.5, which the extension fixes.
// What the specification leaves to the renderer is taken as three.js 0.187 takes it: roughness and clearcoat
// roughness held at 0.045 or above (the note in "Specular BRDF" asks for some least alpha), the sheen's visibility
// and albedo table (charlie_sheen.h). Single scattering only, as Appendix B writes it (its "Discussion" names the
// multiple scattering a renderer may add; three.js adds Fdez-Aguera's under image-based light, which this does not
// model). Everything but the clearcoat is reciprocal; the clearcoat's Fresnel is the view's. fresnel_mix's coupling
// (1 - max F at each half vector) is not energy-conserving, as Appendix B's "Discussion" says: a white dielectric
// reflects at most 1 near the normal but gains toward grazing views (1.68 at roughness 0.045, 86 degrees).
// Not here: transmission, volume and diffuse transmission (KHR_materials_transmission, _volume,
// _diffuse_transmission), which an opaque fitted dielectric does not need; their parameters must be 0.
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

// The material's factors (no textures), by glTF's names in snake case, with glTF's defaults.
struct GltfPbrParameters {
  Rgb base_color = Rgb::Ones();       // baseColorFactor (rgb; alpha is 1, opaque)
  double metallic = 1.0;              // metallicFactor
  double roughness = 1.0;             // roughnessFactor
  double ior = 1.5;                   // KHR_materials_ior: >= 1 (its special value 0 is not taken)
  double specular = 1.0;              // KHR_materials_specular specularFactor, in [0, 1]
  Rgb specular_color = Rgb::Ones();   // specularColorFactor, each >= 0
  double clearcoat = 0.0;             // KHR_materials_clearcoat clearcoatFactor, in [0, 1]
  double clearcoat_roughness = 0.0;   // clearcoatRoughnessFactor, in [0, 1]
  Rgb sheen_color = Rgb::Zero();      // KHR_materials_sheen sheenColorFactor, in [0, 1]
  double sheen_roughness = 0.0;       // sheenRoughnessFactor, in [0, 1]
  double transmission = 0.0;          // KHR_materials_transmission transmissionFactor: must be 0 for now
  double diffuse_transmission = 0.0;  // KHR_materials_diffuse_transmission diffuseTransmissionFactor: must be 0
  double thickness = 0.0;             // KHR_materials_volume thicknessFactor: must be 0 for now
};

// The lobes as they enter f cos(theta_i), each already weighted by the layering above.
struct GltfPbrLobes {
  Rgb clearcoat = Rgb::Zero(), sheen = Rgb::Zero(), specular = Rgb::Zero(), diffuse = Rgb::Zero();
  Rgb sum() const { return clearcoat + sheen + specular + diffuse; }
};

class GltfPbr {
 public:
  static constexpr int kAngles = 33;                // view angles of the albedo tables, 0 to 90 degrees
  static constexpr double kLeastRoughness = 0.045;  // three.js's hold on roughness and clearcoat roughness

  // Throws ParameterError naming the factor out of its range (the extensions' schemas') or not built.
  explicit GltfPbr(const GltfPbrParameters& parameters);

  const GltfPbrParameters& parameters() const { return parameters_; }

  // The same material with base_color replaced (each in [0, 1]): no table depends on it, so this costs a copy.
  GltfPbr with_base_color(const Rgb& base_color) const;

  GltfPbrLobes lobes_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const;
  Rgb brdf_cosine_weighted(const Vec3& omega_i, const Vec3& omega_o) const;

  // int f cos(theta_i) d omega_i for the view at cosine mu_o: what the surface sends toward the view under a white
  // sky. From tables integrated once at construction (below), interpolated in the view's angle.
  Rgb albedo(double mu_o) const;

  // The same with base_color replaced by `base`: every lobe is linear in it, so the fit solves for it in closed form.
  Rgb albedo_with_diffuse_color(double mu_o, const Rgb& base) const;

 private:
  // For each view angle, the integrals over the light of what multiplies each parameter (S the sheen's scaling):
  // the dielectric's F D V cos S (RGB), its diffuse weight (1 - max F) cos S / pi, the metal's D V cos S and
  // D V w cos S, the sheen lobe's D V cos and the coat's D V cos.
  struct Tables {
    std::array<Rgb, kAngles> dielectric_specular{};
    std::array<double, kAngles> diffuse_weight{}, metal{}, metal_edge{}, sheen{}, coat{};
  };
  Rgb dielectric_fresnel(double cos_vh) const;  // F above, RGB
  double sheen_scaling(double mu_i, double mu_o) const;
  double coat_fresnel(double mu_o) const;
  void integrate_tables();

  GltfPbrParameters parameters_;
  double alpha_ = 0.0, coat_alpha_ = 0.0;
  Rgb f0_ = Rgb::Constant(0.04);
  double f90_ = 1.0;
  Tables tables_;
};

}  // namespace skinlayer
