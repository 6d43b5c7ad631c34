// The one GL renderer of the previewer: the same code draws into a GLFW window and into an OSMesa context; only
// context creation differs. It owns the shader programs and the table textures; a GL 3.3+ core context must be
// current when it is created, used and destroyed.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "app/gl/gl_objects.h"
#include "app/render/environment_map.h"
#include "app/render/environment_textures.h"
#include "app/render/render_target.h"
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
  MicrofacetModel microfacet = MicrofacetModel::Multiple;
};

enum class ToneMap { Exponential, Aces, None };  // 1 - e^{-x}; ACES (Narkowicz 2015); clamped
enum class EnvironmentBackground { Hide, Show, Blur };

// How the uploaded environment (Renderer::upload_environment) lights the sphere.
struct EnvironmentView {
  double rotation = 0.0;  // radians about +y (the camera's up)
  double scale = 1.0;     // 2^EV
  EnvironmentBackground background = EnvironmentBackground::Show;
};

// The flat backdrop of a picture (where no environment shows behind the sphere), as a display colour: linear RGB.
// It is no light: linear output (SphereView::linear_output, `render -o x.hdr`) writes zero radiance there instead.
inline constexpr std::array<float, 3> kFlatBackdrop = {0.02f, 0.02f, 0.025f};

struct SphereView {
  glm::dvec3 light = {0.0, 0.0, 1.0};     // unit vector toward the light; camera frame, +z toward viewer
  double irradiance = 3.141592653589793;  // E on a plane normal to the beam (pi: white Lambert -> cos); 0 off
  double exposure = 1.0;                  // linear multiplier before the tone map
  ToneMap tone_map = ToneMap::Exponential;
  bool linear_output = false;                     // write linear radiance (float targets, .hdr, tests); the flat
                                                  // backdrop is then zero radiance
  std::optional<EnvironmentView> environment;     // set: add the environment's estimate and show its background
  // The directional light's subsurface term spread over the sphere by the slot's profile (Renderer::upload_spread),
  // where the slot has one; else where the light falls, as without.
  bool spread = false;
};

// The angle past which the spread subsurface term reads the tables at this incident angle (shaders/shading.glsl):
// just short of grazing, where the light that bleeds past the terminator entered.
inline constexpr double kSpreadMaxTheta = 1.5620696805349968;  // 89.5 degrees

// The progressive estimate of the sphere's radiance under an environment (shaders/env_accumulate.frag): a float
// target over the sphere's view holding the sum of estimates (RGB) and their count (A). Its size may be below the
// view's (the previewer's quick look); the display filters it bilinearly. Clear it whenever anything drawn changes.
class EnvironmentAccumulation {
 public:
  // `seed` separates the random streams (the per-pixel shifts of the sample sequence) of accumulations.
  EnvironmentAccumulation(int width, int height, unsigned seed = 0)
      : target_(width, height, PixelFormat::Rgba32F), seed_(seed) {
    clear();
  }
  void clear();
  int samples() const { return samples_; }
  const RenderTarget& target() const { return target_; }

 private:
  friend class Renderer;
  RenderTarget target_;
  int samples_ = 0;  // per pixel so far: the next pass starts at this index of the sequence
  unsigned seed_ = 0;
};

struct LobeView {
  double theta_i = 0.7853981633974483;  // incident angle, radians
  bool log_scale = false;
  double peak = 1.0;             // BSDF value [1/sr] drawn at the outer circle
  double decades = 3.0;          // log scale: decades between the outer circle and the centre
  bool linear_output = false;    // write (total radius, subsurface radius, pixel radius) in RGB (tests)
  UnscatteredPlane unscattered;  // the shown model's unscattered BTDF in the plane of incidence at theta_i
  bool outline = false;          // draw only the total lobe's outline, over what is drawn (the A/B comparison)
};

// Half-size of a view in units of the sphere radius / plot radius: the larger axis shows `margin` radii.
std::array<double, 2> view_extent(const Viewport& viewport, double margin);

class Renderer {
 public:
  // Table slots: slot 0 holds the shown material; the side-by-side comparison puts more models in 1 and 2; the
  // A/B comparison's pinned material is in kPinnedSlot.
  static constexpr int kTableSlots = 4;
  static constexpr int kPinnedSlot = 3;

  Renderer();

  // Keeps the data too: the lobe plot sums its in-plane profile from it (app/render/lobe_profile.h).
  void upload(TableTextureData tables, int slot = 0);
  // The slot's profile pre-integrated over the sphere (core/spatial/curvature_spread.h): D(theta) at theta_k =
  // pi k / (count - 1), RGB per sample; empty: none (the subsurface term stays where the light falls).
  void upload_spread(const std::vector<float>& rgb, int slot = 0);
  bool has_spread(int slot = 0) const { return slots_.at(static_cast<std::size_t>(slot)).spread_samples > 0; }
  const TableTextureData& table_data(int slot) const { return slots_.at(static_cast<std::size_t>(slot)).data; }

  // Makes `map` the environment that EnvironmentView lights with: its map (mipmapped, for the blurred background)
  // and its luminance distribution. Throws std::runtime_error for a black one. Under a non-empty `key` it is kept
  // after another is shown, within a budget (environment_textures.h), for show_kept_environment.
  void upload_environment(const EnvironmentMap& map, std::string key = {});
  // Shows the environment kept under `key` again, without an upload; false when none is kept under it.
  bool show_kept_environment(const std::string& key);
  // Adds `samples` estimates per pixel (3 directions each) to the accumulation, for the table slot's material; the
  // accumulation covers a view of the sphere with the given aspect. Any number of samples: they are drawn in as many
  // draws as llvmpipe's loop limit needs (renderer.cpp, samples_per_draw). Leaves the default framebuffer bound.
  void accumulate_environment(EnvironmentAccumulation& accumulation, const EnvironmentView& environment,
                              const SurfaceParams& surface, int samples, int slot = 0) const;

  // With view.environment set, `environment` is the accumulation to show (null: none yet).
  void draw_sphere(const SphereView& view, const SurfaceParams& surface, const Viewport& viewport, int slot = 0,
                   const EnvironmentAccumulation* environment = nullptr) const;
  // The A/B comparison: slot_a's sphere left of the split (a fraction of the viewport's width) and slot_b's right of
  // it, under the same view, with a thin light line between them.
  void draw_split_sphere(const SphereView& view, const std::array<SurfaceParams, 2>& surfaces,
                         const std::array<int, 2>& slots,
                         const std::array<const EnvironmentAccumulation*, 2>& environments, const Viewport& viewport,
                         double split) const;
  void draw_lobes(const LobeView& view, const SurfaceParams& surface, const Viewport& viewport, int slot = 0) const;

  static constexpr double kSphereMargin = 1.08;
  static constexpr double kLobeMargin = 1.1;

 private:
  struct TableSlot {
    gl::Texture reflection;
    gl::Texture transmission;
    TableTextureData data;  // what the textures hold
    gl::Texture spread;     // D(theta), RGB, one row
    int spread_samples = 0;
    gl::Texture multiple_lobe;  // the multiply scattered reflection's samples, R (shaders/unscattered.glsl)
  };

  void bind_tables(GLuint program, int slot) const;
  // Uses the program on the viewport with a slot's tables, the view extent and the surface parameters set.
  GLuint begin_view(GLuint program, const SurfaceParams& surface, const Viewport& viewport, double margin,
                    int slot) const;

  void bind_environment(GLuint program, const EnvironmentView& environment) const;

  gl::Program sphere_;
  gl::Program lobe_;
  gl::Program accumulate_;
  KeptEnvironments environments_;
  gl::Texture unscattered_plane_;  // the lobe plot's in-plane unscattered BTDF, refilled by every draw_lobes
  gl::Texture lobe_profile_;       // the lobe plot's in-plane subsurface profile, refilled by every draw_lobes
  gl::VertexArray vertex_array_;
  std::array<TableSlot, kTableSlots> slots_;
};

}  // namespace skinlayer
