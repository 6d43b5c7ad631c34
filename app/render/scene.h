// What one picture shows: the sphere, the polar lobes, or both side by side, and how the views share the frame.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "app/render/renderer.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

// Compare: three spheres under the same light, Lambert | Hanrahan-Krueger | the layer model (Stam's last results
// slide), drawn from renderer slots 1, 2 and 0.
enum class ViewKind { Sphere, Polar, Both, Compare };

// "sphere", "polar", "both", "compare"; nullopt for anything else.
std::optional<ViewKind> parse_view_kind(std::string_view name);
std::string_view view_kind_name(ViewKind view);

// The renderer slot of each sphere of the Compare view, left to right, and the model it shows. A model's slot is
// its enum value (Stam 0, Lambert 1, Hanrahan-Krueger 2), as the previewer uploads them.
inline constexpr std::array<int, 3> kCompareSlots = {1, 2, 0};
inline constexpr std::array<SubsurfaceModel, 3> kCompareModels = {
    SubsurfaceModel::Lambert, SubsurfaceModel::HanrahanKrueger, SubsurfaceModel::Stam};

struct Scene {
  ViewKind view = ViewKind::Both;
  SphereView sphere;
  LobeView lobes;
  SurfaceParams surface;
};

// A light at polar angle theta from the view direction and azimuth phi (radians), as a unit vector in the camera
// frame (+z toward the viewer, +x right, +y up).
glm::dvec3 light_direction(double theta, double phi);

// The scene for a solved material: light, exposure, and the lobe plot scaled so that its largest value (BRDF or
// BTDF in the plane of incidence, from the CPU evaluation) reaches the outer circle. `previous`: the scene shown
// before, whose sampled unscattered lobe is reused when the interfaces, the depth and the light's angle are the same.
Scene make_scene(const ColorTables& tables, ViewKind view, double light_theta, double light_phi, double exposure,
                 bool log_scale, const Scene* previous = nullptr);

// Viewports of the scene's views in a width x height frame (sphere left, polar right for Both; three equal
// columns for Compare).
std::vector<Viewport> scene_viewports(ViewKind view, int width, int height);

// Clears the bound framebuffer and draws every view of the scene; `environment`: the sphere's estimate under
// scene.sphere.environment (Renderer::accumulate_environment), if any.
void draw_scene(const Renderer& renderer, const Scene& scene, int width, int height,
                const EnvironmentAccumulation* environment = nullptr);

}  // namespace skinlayer
