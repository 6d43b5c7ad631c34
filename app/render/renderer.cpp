#include "app/render/renderer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "app/render/lobe_profile.h"
#include "app/render/shader_sources.h"

namespace skinlayer {
namespace {

// Every program: the version line, then the table layout, the GLSL twins of core, the table lookups, the sphere's
// environment and shading where it draws the sphere, the stage.
gl::Program build(std::string_view fragment, bool sphere) {
  const std::string_view version = shader_source("version.glsl");
  const std::vector<std::string_view> vertex = {version, shader_source("fullscreen.vert")};
  std::vector<std::string_view> pieces = {version, shader_source("table_layout.h"), shader_source("common.glsl"),
                                          shader_source("tables.glsl"), shader_source("unscattered.glsl")};
  if (sphere) pieces.insert(pieces.end(), {shader_source("environment.glsl"), shader_source("shading.glsl")});
  pieces.push_back(shader_source(fragment));
  return gl::link_program(vertex, pieces);
}

GLint location(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

// The most azimuth samples of a multiply scattered lobe the shaders hold (kMultipleMaxAzimuths in
// shaders/unscattered.glsl).
constexpr int kMultipleMaxAzimuths = 32;

// The lobe whose reflection the shaders evaluate: a rough top's, or on BottomOnly its interface's (at most one).
const MultipleScatteringLobe* multiple_reflection_lobe(const UnscatteredLight& light) {
  return light.top_multiple() != nullptr ? light.top_multiple() : light.bottom_multiple();
}

// Every table texture is filtered linearly and clamped to its edges (shaders/table_layout.h).
void set_linear_clamped(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void upload_array(GLuint texture, int size, int modes, const std::vector<float>& texels) {
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, size, size, std::max(modes, 1), 0, GL_RGBA, GL_FLOAT,
               texels.empty() ? nullptr : texels.data());
  set_linear_clamped(GL_TEXTURE_2D_ARRAY);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

// A float 2D texture refilled for one draw on texture unit `unit`, bound to the sampler `name`.
void bind_refilled_2d(GLuint program, const char* name, int unit, GLuint texture, GLint internal_format, GLenum format,
                      int width, int height, const float* texels) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, GL_FLOAT, texels);
  set_linear_clamped(GL_TEXTURE_2D);
  glUniform1i(location(program, name), unit);
}

// llvmpipe (Mesa's gallivm) ends the loops of a shader invocation once they have run LP_MAX_TGSI_LOOP_ITERATIONS =
// 65535 iterations together (one counter shared by every loop, per group of 8 pixels), silently: a draw of too many
// samples drops the rest and darkens the estimate, unevenly from group to group (a 1024-sample draw of the paper's
// default, 16 modes, came out 15% dark). So a pass is drawn in pieces whose loops stay well under the limit. Loop
// iterations per sample of shaders/env_accumulate.frag: three table sums of `modes` terms (tables.glsl), the two
// binary searches of the environment's CDFs (environment.glsl, about log2 of each side), the Sobol point's bits
// (at most 32), the multiply scattered lobe's (unscattered.glsl: its azimuth bisection, two polar stencils of 4 and
// their 4 x 4 pairs; twice their count, which is what one call of 1024 samples needed to add up as 64 calls of 16 do,
// tests/app/render/environment_render_test.cpp) and the sample loop itself.
int samples_per_draw(int modes, int environment_width, int environment_height) {
  const int searches = std::bit_width(static_cast<unsigned>(environment_width) + 1u) +
                       std::bit_width(static_cast<unsigned>(environment_height) + 1u);
  constexpr int kMultipleLobeIterations =
      2 * (std::bit_width(static_cast<unsigned>(kMultipleMaxAzimuths)) + 2 * 4 + 4 + 4 * 4);
  const int per_sample = 3 * modes + searches + 32 + kMultipleLobeIterations + 1;
  return std::max(1, 49152 / per_sample);
}

}  // namespace

std::array<double, 2> view_extent(const Viewport& viewport, double margin) {
  const double shorter = std::max(1, std::min(viewport.width, viewport.height));
  return {margin * viewport.width / shorter, margin * viewport.height / shorter};
}

void EnvironmentAccumulation::clear() {
  target_.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  RenderTarget::unbind();
  samples_ = 0;
}

Renderer::Renderer()
    : sphere_(build("sphere.frag", true)),
      lobe_(build("lobe.frag", false)),
      accumulate_(build("env_accumulate.frag", true)),
      unscattered_plane_(gl::create_texture()),
      lobe_profile_(gl::create_texture()),
      vertex_array_(gl::create_vertex_array()) {
  const TableTextureData empty{2, 0, std::vector<float>(16, 0.0f), std::vector<float>(16, 0.0f), {}};
  for (int slot = 0; slot < kTableSlots; ++slot) {
    slots_[slot].reflection = gl::create_texture();
    slots_[slot].transmission = gl::create_texture();
    slots_[slot].spread = gl::create_texture();
    slots_[slot].multiple_lobe = gl::create_texture();
    upload(empty, slot);
    upload_spread({}, slot);
  }
  upload_environment(*builtin_environment("furnace"), "furnace");
  gl::check_errors("Renderer()");
}

void Renderer::upload_environment(const EnvironmentMap& map, std::string key) {
  environments_.add(std::move(key), upload_environment_textures(map));
}

bool Renderer::show_kept_environment(const std::string& key) { return environments_.show(key); }

// The environment's textures on units 4-7 and its uniforms.
void Renderer::bind_environment(GLuint program, const EnvironmentView& environment) const {
  const EnvironmentTextures& shown = environments_.shown();
  const std::array<std::pair<const char*, GLuint>, 4> textures = {
      std::pair{"u_env", shown.radiance.get()}, std::pair{"u_env_density", shown.density.get()},
      std::pair{"u_env_marginal", shown.marginal.get()}, std::pair{"u_env_conditional", shown.conditional.get()}};
  for (std::size_t k = 0; k < textures.size(); ++k) {
    glActiveTexture(GL_TEXTURE4 + static_cast<GLenum>(k));
    glBindTexture(GL_TEXTURE_2D, textures[k].second);
    glUniform1i(location(program, textures[k].first), 4 + static_cast<int>(k));
  }
  glActiveTexture(GL_TEXTURE0);
  glUniform1f(location(program, "u_env_scale"), static_cast<float>(environment.scale));
  const glm::mat3 from_world(environment_from_world(environment.rotation));
  glUniformMatrix3fv(location(program, "u_env_from_world"), 1, GL_FALSE, glm::value_ptr(from_world));
}

void Renderer::accumulate_environment(EnvironmentAccumulation& accumulation, const EnvironmentView& environment,
                                      const SurfaceParams& surface, int samples, int slot) const {
  const RenderTarget& target = accumulation.target_;
  target.bind();
  const GLuint program =
      begin_view(accumulate_.get(), surface, Viewport{0, 0, target.width(), target.height()}, kSphereMargin, slot);
  bind_environment(program, environment);
  glUniform1ui(location(program, "u_seed"), accumulation.seed_);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glBindVertexArray(vertex_array_.get());
  const EnvironmentTextures& shown = environments_.shown();
  const int per_draw =
      samples_per_draw(slots_.at(static_cast<std::size_t>(slot)).data.modes, shown.width, shown.height);
  for (int left = samples; left > 0;) {
    const int draw = std::min(left, per_draw);
    glUniform1i(location(program, "u_samples"), draw);
    glUniform1i(location(program, "u_first_sample"), accumulation.samples_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    accumulation.samples_ += draw;
    left -= draw;
  }
  glDisable(GL_BLEND);
  RenderTarget::unbind();
  gl::check_errors("Renderer::accumulate_environment");
}

void Renderer::upload(TableTextureData tables, int slot) {
  TableSlot& target = slots_.at(static_cast<std::size_t>(slot));
  upload_array(target.reflection.get(), tables.size, tables.modes, tables.reflection);
  upload_array(target.transmission.get(), tables.size, tables.modes, tables.transmission);
  // The multiply scattered reflection lobe's samples (shaders/unscattered.glsl), or one zero texel.
  const MultipleScatteringLobe* lobe = multiple_reflection_lobe(tables.unscattered);
  std::vector<float> samples(1, 0.0f);
  int azimuths = 1, rows = 1;
  if (lobe != nullptr) {
    const Eigen::MatrixXd& values = lobe->reflection_samples(true);
    azimuths = static_cast<int>(values.cols());
    rows = static_cast<int>(values.rows());
    samples.resize(static_cast<std::size_t>(values.size()));
    for (Eigen::Index r = 0; r < values.rows(); ++r) {
      for (Eigen::Index c = 0; c < values.cols(); ++c) {
        samples[static_cast<std::size_t>(r * values.cols() + c)] = static_cast<float>(values(r, c));
      }
    }
  }
  glBindTexture(GL_TEXTURE_2D, target.multiple_lobe.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, azimuths, rows, 0, GL_RED, GL_FLOAT, samples.data());
  set_linear_clamped(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  target.data = std::move(tables);
  gl::check_errors("Renderer::upload");
}

void Renderer::upload_spread(const std::vector<float>& rgb, int slot) {
  TableSlot& target = slots_.at(static_cast<std::size_t>(slot));
  if (rgb.size() % 3 != 0 || rgb.size() == 3) throw std::invalid_argument("upload_spread: RGB samples, none or >= 2");
  const std::vector<float> none(6, 0.0f);
  const std::vector<float>& texels = rgb.empty() ? none : rgb;
  glBindTexture(GL_TEXTURE_2D, target.spread.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, static_cast<int>(texels.size() / 3), 1, 0, GL_RGB, GL_FLOAT, texels.data());
  set_linear_clamped(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  target.spread_samples = static_cast<int>(rgb.size() / 3);
  gl::check_errors("Renderer::upload_spread");
}

void Renderer::bind_tables(GLuint program, int slot) const {
  const TableSlot& tables = slots_.at(static_cast<std::size_t>(slot));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tables.reflection.get());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tables.transmission.get());
  glUniform1i(location(program, "u_reflection"), 0);
  glUniform1i(location(program, "u_transmission"), 1);
  glUniform1i(location(program, "u_modes"), tables.data.modes);
  // The closed-form unscattered BRDF of an open top over a rough bottom (shaders/unscattered.glsl).
  const UnscatteredLight& light = tables.data.unscattered;
  glUniform1i(location(program, "u_unscattered_reflects"), light.path() == UnscatteredPath::BottomOnly ? 1 : 0);
  glUniform1f(location(program, "u_tau"), static_cast<float>(light.tau()));
  glUniform1f(location(program, "u_bottom_eta"), static_cast<float>(light.bottom().eta));
  glUniform1f(location(program, "u_bottom_sigma"), static_cast<float>(light.bottom().sigma));
  glUniform1i(location(program, "u_bottom_microfacet"), light.bottom().microfacet == MicrofacetModel::Multiple ? 1 : 0);
  // The multiply scattered reflection lobe: a rough top's, or an open top's interface under the slab.
  const MultipleScatteringLobe* lobe = multiple_reflection_lobe(light);
  glUniform1i(location(program, "u_multiple_reflects"),
              lobe == nullptr ? 0 : (light.path() == UnscatteredPath::BottomOnly ? 2 : 1));
  glUniform1f(location(program, "u_multiple_weight"), static_cast<float>(light.weight()));
  std::array<float, kMultipleMaxAzimuths> azimuths{};
  const std::size_t count = lobe != nullptr ? lobe->azimuths().size() : 0;
  if (count > azimuths.size()) throw std::logic_error("bind_tables: the lobe has more azimuths than the shader holds");
  for (std::size_t a = 0; a < count; ++a) azimuths[a] = static_cast<float>(lobe->azimuths()[a]);
  glUniform1fv(location(program, "u_multiple_azimuths"), kMultipleMaxAzimuths, azimuths.data());
  glUniform1i(location(program, "u_multiple_azimuth_count"), static_cast<int>(count));
  glActiveTexture(GL_TEXTURE10);
  glBindTexture(GL_TEXTURE_2D, tables.multiple_lobe.get());
  glUniform1i(location(program, "u_multiple_samples"), 10);
  glActiveTexture(GL_TEXTURE0);
}

GLuint Renderer::begin_view(GLuint program, const SurfaceParams& surface, const Viewport& viewport, double margin,
                            int slot) const {
  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  glUseProgram(program);
  bind_tables(program, slot);
  const std::array<double, 2> extent = view_extent(viewport, margin);
  glUniform2f(location(program, "u_extent"), static_cast<float>(extent[0]), static_cast<float>(extent[1]));
  glUniform1f(location(program, "u_eta"), static_cast<float>(surface.eta));
  glUniform1f(location(program, "u_sigma"), static_cast<float>(surface.sigma));
  glUniform1i(location(program, "u_microfacet"), surface.microfacet == MicrofacetModel::Multiple ? 1 : 0);
  return program;
}

void Renderer::draw_sphere(const SphereView& view, const SurfaceParams& surface, const Viewport& viewport, int slot,
                           const EnvironmentAccumulation* environment) const {
  const GLuint program = begin_view(sphere_.get(), surface, viewport, kSphereMargin, slot);
  glUniform1i(location(program, "u_tonemap"), static_cast<int>(view.tone_map));
  glUniform1i(location(program, "u_environment"), view.environment && environment ? 1 : 0);
  glUniform1i(location(program, "u_env_background"),
              view.environment ? static_cast<int>(view.environment->background) : 0);
  // Every sampler on a unit of its own, used or not (two sampler types on one unit fail the draw).
  bind_environment(program, view.environment.value_or(EnvironmentView{}));
  glActiveTexture(GL_TEXTURE8);
  glBindTexture(GL_TEXTURE_2D,
                environment ? environment->target().color_texture() : environments_.shown().density.get());
  if (environment) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glUniform1i(location(program, "u_accumulation"), 8);
  const TableSlot& tables = slots_.at(static_cast<std::size_t>(slot));
  glActiveTexture(GL_TEXTURE9);
  glBindTexture(GL_TEXTURE_2D, tables.spread.get());
  glUniform1i(location(program, "u_spread_table"), 9);
  glUniform1i(location(program, "u_spread"), view.spread && tables.spread_samples > 0 ? 1 : 0);
  glUniform1f(location(program, "u_spread_max_theta"), static_cast<float>(kSpreadMaxTheta));
  glActiveTexture(GL_TEXTURE0);
  glUniform3fv(location(program, "u_light"), 1, glm::value_ptr(glm::vec3(view.light)));
  glUniform1f(location(program, "u_irradiance"), static_cast<float>(view.irradiance));
  glUniform1f(location(program, "u_exposure"), static_cast<float>(view.exposure));
  glUniform1i(location(program, "u_output_linear"), view.linear_output ? 1 : 0);
  // A hidden environment, or none, leaves the flat backdrop: a display colour, or in linear radiance no light at all.
  const std::array<float, 3> backdrop = view.linear_output ? std::array<float, 3>{} : kFlatBackdrop;
  glUniform3f(location(program, "u_background"), backdrop[0], backdrop[1], backdrop[2]);
  glBindVertexArray(vertex_array_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  gl::check_errors("Renderer::draw_sphere");
}

void Renderer::draw_split_sphere(const SphereView& view, const std::array<SurfaceParams, 2>& surfaces,
                                 const std::array<int, 2>& slots,
                                 const std::array<const EnvironmentAccumulation*, 2>& environments,
                                 const Viewport& viewport, double split) const {
  const int line = viewport.x + static_cast<int>(std::lround(std::clamp(split, 0.0, 1.0) * viewport.width));
  glEnable(GL_SCISSOR_TEST);
  glScissor(viewport.x, viewport.y, line - viewport.x, viewport.height);
  draw_sphere(view, surfaces[0], viewport, slots[0], environments[0]);
  glScissor(line, viewport.y, viewport.x + viewport.width - line, viewport.height);
  draw_sphere(view, surfaces[1], viewport, slots[1], environments[1]);
  glScissor(line - 1, viewport.y, 2, viewport.height);
  glClearColor(0.85f, 0.85f, 0.85f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  gl::check_errors("Renderer::draw_split_sphere");
}

void Renderer::draw_lobes(const LobeView& view, const SurfaceParams& surface, const Viewport& viewport,
                          int slot) const {
  const GLuint program = begin_view(lobe_.get(), surface, viewport, kLobeMargin, slot);
  glUniform1f(location(program, "u_theta_i"), static_cast<float>(view.theta_i));
  glUniform1i(location(program, "u_log_scale"), view.log_scale ? 1 : 0);
  glUniform1f(location(program, "u_peak"), static_cast<float>(view.peak));
  glUniform1f(location(program, "u_decades"), static_cast<float>(view.decades));
  glUniform1i(location(program, "u_output_linear"), view.linear_output ? 1 : 0);
  glUniform1i(location(program, "u_outline"), view.outline ? 1 : 0);
  const UnscatteredPlane& plane = view.unscattered;
  const std::vector<float> none(2, 0.0f);
  const std::vector<float>& samples = plane.btdf.size() >= 2 ? plane.btdf : none;
  bind_refilled_2d(program, "u_unscattered_plane", 2, unscattered_plane_.get(), GL_R32F, GL_RED,
                   static_cast<int>(samples.size()), 1, samples.data());
  glUniform4f(location(program, "u_unscattered_map"), static_cast<float>(plane.centre), static_cast<float>(plane.scale),
              static_cast<float>(plane.u_min), static_cast<float>(plane.u_max));
  const TableTextureData& tables = slots_.at(static_cast<std::size_t>(slot)).data;
  const std::vector<float> profile = lobe_profile(tables, view.theta_i);
  bind_refilled_2d(program, "u_lobe_profile", 3, lobe_profile_.get(), GL_RGBA32F, GL_RGBA, tables.size,
                   kLobeProfileRows, profile.data());
  glBindVertexArray(vertex_array_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glActiveTexture(GL_TEXTURE0);
  gl::check_errors("Renderer::draw_lobes");
}

}  // namespace skinlayer
