#include "app/validate/validation_grid.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace skinlayer::validation {
namespace {

// Path counts per kind of set. A short walk (a few events) costs ~0.5 us per path on 2 threads; a semi-infinite
// layer with Omega 0.99 walks longer (~5 us). Quick: ~2 s per set on 2 cores; full: ten times the paths.
constexpr std::uint64_t kShortFull = 40'000'000, kShortQuick = 4'000'000;
constexpr std::uint64_t kLongFull = 4'000'000, kLongQuick = 400'000;

ValidationSet set(std::string name, std::string description, const Material& material, double theta_i_deg,
                  bool long_walks = false) {
  return {std::move(name),
          std::move(description),
          material,
          theta_i_deg,
          long_walks ? kLongFull : kShortFull,
          long_walks ? kLongQuick : kShortQuick};
}

Material with_transparency(Material material, double transparency) {
  material.tau = optical_depth_from_transparency(transparency);
  return material;
}

}  // namespace

std::vector<ValidationSet> validation_grid() {
  const Material paper;  // sigma 0.5, eta 1.4, T 0.2, Omega 1, g 0.8, air below (Stam's figures)
  std::vector<ValidationSet> grid;

  // The paper's figure settings.
  grid.push_back(set("paper-default", "the paper's default layer", paper, 45.0));
  grid.push_back(set("paper-grazing", "the paper's layer lit at 75 degrees", paper, 75.0));
  Material smooth = with_transparency(paper, 0.1);
  smooth.sigma = 0.1;
  grid.push_back(set("paper-sigma-0.1", "the σ figure's smoothest interfaces (T 0.1)", smooth, 45.0));
  Material deep = with_transparency(paper, 0.0);
  deep.albedo = 0.5;
  grid.push_back(set("paper-deep-omega-0.5", "the lobe-shape figure: semi-infinite, Ω 0.5", deep, 45.0));

  // Phase function: g in {0, 0.5, 0.9} on a half-transparent, nearly white layer.
  Material phase = with_transparency(paper, 0.5);
  phase.albedo = 0.99;
  for (const auto& [name, g] : {std::pair{"g-0", 0.0}, std::pair{"g-0.5", 0.5}, std::pair{"g-0.9", 0.9}}) {
    Material m = phase;
    m.g = g;
    grid.push_back(set(name, "HG asymmetry g on a layer of T 0.5, Ω 0.99", m, 30.0));
  }

  // Single-scattering albedo: Omega in {0.5, 0.99} (1 is the paper's).
  for (const auto& [name, albedo] : {std::pair{"omega-0.5", 0.5}, std::pair{"omega-0.99", 0.99}}) {
    Material m = paper;
    m.albedo = albedo;
    grid.push_back(set(name, "albedo Ω on the paper's layer, lit at 60 degrees", m, 60.0));
  }

  // Roughness: sigma 1 (0.1 and 0.5 above), on the white layer: the Smith losses of both interfaces in full.
  Material rough = paper;
  rough.sigma = 1.0;
  grid.push_back(set("sigma-1", "the roughest interfaces on the paper's white layer", rough, 45.0));

  // Relative index: eta 1 (no interfaces at all) and 2 (1.4 above).
  Material open = with_transparency(paper, 0.5);
  open.eta = 1.0;
  open.albedo = 0.9;
  open.g = 0.5;
  grid.push_back(set("eta-1", "no interfaces: a bare slab of T 0.5, Ω 0.9, g 0.5", open, 30.0));
  Material dense = paper;
  dense.eta = 2.0;
  grid.push_back(set("eta-2", "η 2 on both interfaces of the paper's layer", dense, 45.0));

  // Bottoms: matched, Lambert, and an air interface unlike the top.
  Material matched = paper;
  matched.bottom.kind = BottomKind::Matched;
  grid.push_back(set("bottom-matched", "the paper's layer over an index-matched half-space", matched, 30.0));
  Material bone = paper;
  bone.bottom = parse_bottom("lambert:0.8");
  bone.albedo = 0.9;
  grid.push_back(set("bottom-lambert", "the paper's layer (Ω 0.9) over a Lambertian base A 0.8", bone, 0.0));
  Material unlike = paper;
  unlike.bottom.sigma = 0.2;
  unlike.bottom.eta = 1.2;
  unlike.albedo = 0.95;
  grid.push_back(set("bottom-unlike", "a bottom interface unlike the top (σ3 0.2, η3 1.2), Ω 0.95", unlike, 45.0));
  Material open_bone = with_transparency(open, 0.5);
  open_bone.bottom = parse_bottom("lambert:0.5");
  grid.push_back(set("eta-1-lambert", "no top interface over a Lambertian base A 0.5", open_bone, 60.0));

  // Depth: thin and semi-infinite.
  Material thin = with_transparency(paper, 0.9);
  thin.g = 0.5;
  thin.albedo = 0.99;
  grid.push_back(set("thin", "a thin layer: T 0.9, g 0.5, Ω 0.99", thin, 45.0));
  Material half_space = with_transparency(paper, 0.0);
  half_space.albedo = 0.99;
  half_space.g = 0.0;
  grid.push_back(set("deep-g-0", "semi-infinite, isotropic, Ω 0.99", half_space, 45.0, true));
  half_space.g = 0.9;
  grid.push_back(set("deep-g-0.9", "semi-infinite, g 0.9, Ω 0.99", half_space, 45.0, true));
  Material bare_half_space = half_space;
  bare_half_space.eta = 1.0;
  bare_half_space.albedo = 0.5;
  bare_half_space.g = 0.0;
  grid.push_back(
      set("deep-eta-1", "semi-infinite, no interface, isotropic, Ω 0.5 (Chandrasekhar's H)", bare_half_space, 60.0));
  // Thin layers between sharp interfaces: the light that crosses unscattered makes lobes a degree wide, which only
  // the peak bins can see (issue 10).
  for (const double sigma : {0.2, 0.05}) {
    for (const char* bottom : {"air", "matched"}) {
      Material m = with_transparency(paper, std::string(bottom) == "air" ? 0.5 : 0.2);
      m.sigma = sigma;
      m.albedo = 0.9;
      m.g = 0.5;
      m.bottom = parse_bottom(bottom);
      char name[48], description[96];
      std::snprintf(name, sizeof name, "sharp-%g-%s", sigma, bottom);
      std::snprintf(description, sizeof description,
                    "a thin layer (T %g, Ω 0.9, g 0.5) between σ %g interfaces, %s below",
                    std::string(bottom) == "air" ? 0.5 : 0.2, sigma, bottom);
      grid.push_back(set(name, description, m, 30.0));
    }
  }
  // Stacks (issue 12): two and three layers of very different g and Omega, a rough interface between layers, and
  // a thin layer over a semi-infinite one.
  Material two = paper;
  two.tau = 0.5;
  two.albedo = 0.9;
  two.g = 0.9;
  two.below = {{2.0, 0.99, 0.0, std::nullopt}};
  grid.push_back(set("stack-2", "two layers: τ 0.5, Ω 0.9, g 0.9 over τ 2, Ω 0.99, g 0", two, 30.0));
  Material three = paper;
  three.tau = 0.3;
  three.albedo = 0.95;
  three.g = 0.8;
  three.below = {{0.5, 0.6, -0.3, std::nullopt}, {1.0, 0.99, 0.5, std::nullopt}};
  three.bottom.kind = BottomKind::Matched;
  grid.push_back(
      set("stack-3", "three layers (g 0.8, -0.3, 0.5; Ω 0.95, 0.6, 0.99) over a matched half-space", three, 45.0));
  Material inner = paper;
  inner.sigma = 0.3;
  inner.tau = 0.4;
  inner.albedo = 0.95;
  inner.g = 0.5;
  inner.below = {{1.5, 0.9, 0.8, LayerInterface{0.4, 1.15}}};
  grid.push_back(
      set("stack-interface", "two layers with a rough interface between them (σ 0.4, η 1.15), air below", inner, 45.0));
  Material coat = paper;
  coat.sigma = 0.2;
  coat.eta = 1.5;
  coat.tau = optical_depth_from_transparency(0.9);
  coat.albedo = 0.99;
  coat.g = 0.8;
  coat.below = {{INFINITY, 0.9, 0.3, std::nullopt}};
  grid.push_back(
      set("stack-thin-over-deep", "a thin layer (T 0.9, g 0.8) over a semi-infinite one (Ω 0.9, g 0.3)", coat, 30.0));
  // The light that meets the microsurface more than once (issue 53), where its lobe carries the most: grazing light
  // on a thin layer, whose interfaces send it back and forth; the roughest interfaces on a thin layer; and a low
  // index contrast, where that light leaves near the refracted direction.
  Material thin_grazing = thin;
  grid.push_back(set("thin-grazing", "the thin layer (T 0.9, g 0.5, Ω 0.99) lit at 80 degrees", thin_grazing, 80.0));
  Material rough_thin = thin;
  rough_thin.sigma = 1.0;
  grid.push_back(set("sigma-1-thin", "σ 1 on both interfaces of a thin layer (T 0.9, g 0.5, Ω 0.99)", rough_thin, 60.0));
  Material low_contrast = paper;
  low_contrast.eta = 1.2;
  grid.push_back(set("eta-1.2", "η 1.2 on both interfaces of the paper's layer", low_contrast, 45.0));
  for (std::size_t k = 0; k < grid.size(); ++k) grid[k].grid_index = k;
  return grid;
}

}  // namespace skinlayer::validation
