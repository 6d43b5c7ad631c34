// The one GL renderer of the previewer: the same code draws into a GLFW window and into an OSMesa context; only
// context creation differs. It owns the shader programs and the table textures; a GL 3.3+ core context must be
// current when it is created, used and destroyed.
#pragma once

#include <array>

#include "app/gl/gl_objects.h"
#include "app/render/table_textures.h"
#include "app/render/unscattered_plane.h"

namespace skinlayer {

struct Viewport {
  int x = 0;
  int y = 0;  // from the bottom, as glViewport
  int width = 0;
  int height = 0;
};

struct SurfaceParams {
  double eta = 1.4;
  double sigma = 0.5;
};

struct SphereView {
  std::array<double, 3> light = {0.0, 0.0, 1.0};  // unit vector toward the light; camera frame, +z toward viewer
  double irradiance = 3.141592653589793;          // E on a plane normal to the beam (pi: white Lambert -> cos)
  double exposure = 1.0;                          // linear multiplier before the exponential tone map
  bool linear_output = false;                     // write linear radiance (float targets, tests)
};

struct LobeView {
  double theta_i = 0.7853981633974483;  // incident angle, radians
  bool log_scale = false;
  double peak = 1.0;             // BSDF value [1/sr] drawn at the outer circle
  double decades = 3.0;          // log scale: decades between the outer circle and the centre
  bool linear_output = false;    // write (total radius, subsurface radius, pixel radius) in RGB (tests)
  UnscatteredPlane unscattered;  // the shown model's unscattered BTDF in the plane of incidence at theta_i
};

// Half-size of a view in units of the sphere radius / plot radius: the larger axis shows `margin` radii.
std::array<double, 2> view_extent(const Viewport& viewport, double margin);

class Renderer {
 public:
  // Table slots: slot 0 holds the shown material; the side-by-side comparison puts more models in the others.
  static constexpr int kTableSlots = 3;

  Renderer();

  // Keeps the data too: the lobe plot sums its in-plane profile from it (app/render/lobe_profile.h).
  void upload(TableTextureData tables, int slot = 0);

  void draw_sphere(const SphereView& view, const SurfaceParams& surface, const Viewport& viewport, int slot = 0) const;
  void draw_lobes(const LobeView& view, const SurfaceParams& surface, const Viewport& viewport, int slot = 0) const;

  static constexpr double kSphereMargin = 1.08;
  static constexpr double kLobeMargin = 1.1;

 private:
  struct TableSlot {
    gl::Texture reflection;
    gl::Texture transmission;
    TableTextureData data;  // what the textures hold
  };

  void bind_tables(GLuint program, int slot) const;
  // Uses the program on the viewport with a slot's tables, the view extent and the surface parameters set.
  GLuint begin_view(GLuint program, const SurfaceParams& surface, const Viewport& viewport, double margin,
                    int slot) const;

  gl::Program sphere_;
  gl::Program lobe_;
  gl::Texture unscattered_plane_;  // the lobe plot's in-plane unscattered BTDF, refilled by every draw_lobes
  gl::Texture lobe_profile_;       // the lobe plot's in-plane subsurface profile, refilled by every draw_lobes
  gl::VertexArray vertex_array_;
  std::array<TableSlot, kTableSlots> slots_;
};

}  // namespace skinlayer
