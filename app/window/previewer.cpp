#include "app/window/previewer.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/gl/gl_api.h"
#include "app/material/picture_metadata.h"
#include "app/preview/edit_history.h"
#include "app/preview/material_session.h"
#include "app/preview/preview_state.h"
#include "app/preview/recent_files.h"
#include "app/preview/solve_worker.h"
#include "app/preview/view_layout.h"
#include "app/process/heap_retention.h"
#include "app/process/parallel_for.h"
#include "app/process/resident_memory.h"
#include "app/render/environment_preview.h"
#include "app/render/renderer.h"
#include "app/render/scene.h"
#include "app/render/table_textures.h"
#include "app/solution/fitted_tables.h"
#include "app/window/background_jobs.h"
#include "app/window/control_panel.h"
#include "app/window/file_panel.h"
#include "app/window/glfw_window.h"
#include "app/window/help_overlay.h"
#include "app/window/material_files.h"
#include "app/window/one_shot_job.h"
#include "app/window/screenshot.h"
#include "app/window/shortcuts.h"
#include "app/window/spread_job.h"
#include "app/window/test_action_script.h"
#include "app/window/ui_context.h"
#include "app/window/view_overlays.h"
#include "core/conventions.h"

namespace skinlayer {
namespace {

constexpr int kWindowWidth = 1280;  // screen coordinates at content scale 1
constexpr int kWindowHeight = 720;
constexpr int kCaptureSettleFrames = 3;  // frames drawn with the final result before a capture (>= 2: ImGui
                                         // hides auto-sized windows on their first frame)
constexpr double kCaptureTimeoutSeconds = 300.0;
constexpr double kIdleWaitSeconds = 0.1;  // event wait when nothing moves; events and results wake it at once
constexpr double kCaptureWaitSeconds = 1.0 / 60.0;
constexpr int kEagerFrames = 3;                    // frames drawn at full rate after any activity
constexpr double kEagerWaitSeconds = 1.0 / 120.0;  // caps the full rate where vsync does not (e.g. under Xvfb)

class Previewer final : private TestActionTarget {
 public:
  Previewer(const WindowOptions& options, std::ostream& out)
      : out_(out),
        capture_path_(options.capture_path),
        window_(kWindowWidth, kWindowHeight, "skinlayer"),
        imgui_(window_.handle(), window_.content_scale()),
        history_(Edit{options.material, LightState{}}),
        files_(initial_session(options), recent_files_path()),
        script_(options.test_actions),
        worker_(post_empty_event) {
    state_.material = options.material;
    state_.view.view = options.view;
    const cli::LightingFlags& lighting = options.lighting;
    state_.lighting.environment = lighting.environment.value_or("");
    state_.lighting.rotate_degrees = radians_to_degrees(lighting.view.rotation);
    state_.lighting.ev = std::log2(lighting.view.scale);
    state_.lighting.background = lighting.view.background;
    state_.lighting.directional = lighting.directional_light;
    state_.lighting.tone_map = lighting.tone_map;
    capture_samples_ = lighting.samples;
  }

  int run() {
    double timeout = 0.0;
    while (!captured_) {
      if (window_.should_close()) {
        // Closing with unsaved changes asks first (never in capture mode, which edits nothing by hand).
        if (capture_path_ || files_.may_close(state_.material)) break;
        window_.cancel_close();
      }
      wait_events(timeout);
      timeout = frame();
      // The capture waits for the solve of the final parameters: counted from the last scripted action, so that a
      // long script (the soak test's thousands of edits) is not cut short.
      if (capture_path_ &&
          std::chrono::steady_clock::now() - script_.last_action() >
              std::chrono::duration<double>(kCaptureTimeoutSeconds)) {
        throw std::runtime_error("capture: the material was not solved within " +
                                 std::to_string(static_cast<int>(kCaptureTimeoutSeconds)) + " s");
      }
    }
    return 0;
  }

 private:
  // One frame; returns how long the loop may wait for events before the next one.
  double frame() {
    bool activity = take_result();
    activity |= jobs_.take_outcomes(state_.material, out_);
    activity |= take_fit_pin();
    const std::array<int, 2> framebuffer = window_.framebuffer_size();
    if (framebuffer[0] < 1 || framebuffer[1] < 1) return kIdleWaitSeconds;  // minimized: nothing to draw
    update_scene();
    activity |= update_spread();  // after the scene, which a new result remakes
    imgui_.new_frame();
    const std::array<int, 2> size = window_.window_size();
    const PreviewLayout layout = layout_preview(static_cast<float>(size[0]), static_cast<float>(size[1]),
                                                kPanelWidth * imgui_.scale(), state_.view.view);
    const std::array<float, 2> scale = {static_cast<float>(framebuffer[0]) / static_cast<float>(std::max(size[0], 1)),
                                        static_cast<float>(framebuffer[1]) / static_cast<float>(std::max(size[1], 1))};
    PreviewState edited = state_;
    ViewOverlayInput overlay{layout, shown_ ? &plot_tables() : nullptr, scene_.lobes, imgui_.unicode_labels(),
                             scene_.sphere.spread && spread_profile_ ? &*spread_profile_ : nullptr};
    activity |= view_overlays(overlay, edited.light, edited.comparison);
    const PanelActions panel = control_panel(layout.panel, edited, panel_status(), file_section_input());
    if (panel.pin) pin_shown(edited);
    if (panel.pin_fit) start_fit_pin(*panel.pin_fit);
    if (panel.unpin) unpin(edited);
    if (panel.export_bsdf) export_shown(ExportFormat::Bsdf);
    if (panel.export_merl) export_shown(ExportFormat::Merl);
    if (panel.export_rgl) export_shown(ExportFormat::Rgl);
    if (panel.export_blender) export_shown(ExportFormat::Blender);
    if (panel.export_mtlx) export_shown(ExportFormat::MaterialX);
    if (panel.match_srgb) jobs_.start_match(edited.material, *panel.match_srgb);
    // What the panel, the keys, drops, dialogs and the test script ask of this frame, in that order.
    ActionRequests requests{panel.save_screenshot, panel.reset_material, panel.file.undo, panel.file.redo, false, {}};
    if (panel.file.command.kind != FileCommand::Kind::None) requests.file_commands.push_back(panel.file.command);
    const std::vector<Action> actions = pressed_actions(window_.take_key_presses(), ImGui::GetIO().WantTextInput);
    apply_actions(actions, edited, requests);
    activity |= !actions.empty();
    draw_help_overlay(edited.show_help);
    if (requests.reset_material) edited = reset_material(edited);
    state_ = edited;
    for (const std::string& path : window_.take_dropped_paths()) {
      requests.file_commands.push_back({FileCommand::Kind::OpenPath, path});
    }
    if (const FileCommand confirmed = file_dialogs(files_.dialog()); confirmed.kind != FileCommand::Kind::None) {
      requests.file_commands.push_back(confirmed);
    }
    script_.step(TestActionReadiness{shown_ && !solving() && !jobs_.matching() && !fit_job_.running(), resting_,
                                     files_.dialog().kind},
                 *this, requests);
    if (requests.quit) window_.request_close();
    for (const FileCommand& command : requests.file_commands) run_file_command(command);
    if (requests.undo) step_history(history_.undo(current_edit()));
    if (requests.redo) step_history(history_.redo(current_edit()));
    // One slider drag, or one drag of the light on the sphere, is one undo step: it commits on release.
    history_.observe(current_edit(), ImGui::IsAnyItemActive() || script_.dragging());
    window_.set_title(window_title(files_.session(), state_.material, imgui_.unicode_labels()));
    submit_if_needed();

    const ImGuiIO& io = ImGui::GetIO();
    const bool save = requests.save_screenshot;
    activity |= save || requests.reset_material || ImGui::IsAnyItemActive() || io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f ||
                ImGui::IsAnyMouseDown();

    const bool refining = refine_environment(layout, scale, framebuffer, activity) || spread_job_.running();
    draw_views(layout, scale, framebuffer);
    const ExportTarget target = state_.export_options.target;
    if (save && target != ExportTarget::Window) {
      const Rect& rect = target == ExportTarget::Sphere ? layout.sphere : layout.plots;
      if (rect.empty() || !shown_) {
        jobs_.note_export("nothing saved: that view is not on screen");
      } else {
        export_picture(to_viewport(rect, scale, framebuffer[1]), state_.export_options.path);
      }
    }
    imgui_.render();
    if (save && target == ExportTarget::Window) {
      export_picture(Viewport{0, 0, framebuffer[0], framebuffer[1]}, state_.export_options.path);
    }
    capture_if_ready(framebuffer);
    window_.swap_buffers();

    eager_frames_ = activity || refining ? kEagerFrames : std::max(eager_frames_ - 1, 0);
    rest_if_idle(activity);
    if (capture_path_) return kCaptureWaitSeconds;
    return eager_frames_ > 0 ? kEagerWaitSeconds : kIdleWaitSeconds;
  }

  // Once the window comes to rest (no input or result for kEagerFrames frames, no solve, export or match running;
  // an environment's estimate may still refine), the heap's freed pages go back to the kernel, once per rest
  // (app/process/heap_retention.h).
  void rest_if_idle(bool activity) {
    quiet_frames_ = activity ? 0 : quiet_frames_ + 1;
    if (activity) resting_ = false;
    if (resting_ || quiet_frames_ < kEagerFrames || worker_.settling() || jobs_.running() || fit_job_.running()) {
      return;
    }
    release_freed_heap_memory();
    resting_ = true;
  }

  // Uploads a newly finished result; returns true if there was one.
  bool take_result() {
    std::optional<SolveResult> result = worker_.poll();
    if (!result) return false;
    if (!result->error.empty()) {
      error_ = result->error;
      return true;
    }
    for (std::size_t m = 0; m < result->by_model.size(); ++m) {  // renderer slot = model index
      if (result->by_model[m]) renderer_.upload(std::move(result->textures_by_model[m]), static_cast<int>(m));
    }
    result->textures_by_model = {};  // the renderer holds them now
    error_.clear();
    shown_ = std::move(result);
    return true;
  }

  // Whether a profile's material is the shown one, for the profile: the same solve of it, whatever the light or the
  // views.
  bool for_shown(const std::optional<ColorMaterial>& material) const {
    return shown_ && material &&
           same_request(SolveRequest{*material, 0.0, false, SubsurfaceModel::Stam},
                        SolveRequest{shown_->request.material, 0.0, false, SubsurfaceModel::Stam});
  }

  // The sphere's translucency (app/window/spread_job.h): once the shown material's full solve is on screen, its
  // profile is computed on the spread's thread; its outcome, if it still answers the shown material, becomes the
  // texture of the radius shown, redone alone when the radius slider moves. Returns true when something changed.
  bool update_spread() {
    bool changed = false;
    if (std::optional<SpreadOutcome> outcome = spread_job_.take_outcome()) {
      spread_material_ = spread_requested_;
      spread_profile_ = std::move(outcome->profile);
      spread_note_ = outcome->why;
      spread_radius_ = -1.0;
      changed = true;
    }
    const bool wanted = spread_wanted();
    if (wanted && !spread_job_.running() && !for_shown(spread_material_) && !for_shown(spread_requested_)) {
      spread_requested_ = shown_->request.material;
      spread_job_.start(material_document(*spread_requested_));
    }
    const bool current = wanted && spread_profile_ && for_shown(spread_material_);
    if (current && spread_radius_ != state_.view.sphere_radius_mm) {
      try {
        renderer_.upload_spread(spread_texture(*spread_profile_, state_.view.sphere_radius_mm));
      } catch (const std::invalid_argument& error) {  // a profile with no light to spread (albedo 0)
        spread_profile_.reset();
        spread_note_ = error.what();
      }
      spread_radius_ = state_.view.sphere_radius_mm;
      changed = true;
    }
    scene_.sphere.spread = current && spread_profile_.has_value();
    return changed;
  }

  // The translucency applies to the shown material: the layer model's, fully solved.
  bool spread_wanted() const {
    return state_.view.translucency && shown_ && !shown_->preview && error_.empty() &&
           shown_->request.material.model == SubsurfaceModel::Stam;
  }

  // What the panel says of the translucency.
  std::string spread_status() const {
    if (!state_.view.translucency) return "translucency off: the light leaves where it falls";
    if (shown_ && shown_->request.material.model != SubsurfaceModel::Stam) {
      return "translucency: for the layer model only (the sphere shows a comparison model)";
    }
    if (spread_job_.running()) return "translucency: computing the material's profile...";
    if (!shown_ || shown_->preview || !for_shown(spread_material_)) {
      return "translucency: waiting for the full solve";
    }
    if (!spread_profile_) return "no translucency: " + spread_note_;
    return "translucency: the profile spreads the subsurface light";
  }

  // The newest parameters go to the worker once it has finished the previous ones, so that while a slider is
  // dragged every solve is shown (at the solver's pace) and the final parameters always win.
  void submit_if_needed() {
    const SolveRequest request = solve_request(state_);
    if (submitted_ && same_request(*submitted_, request)) return;
    if (worker_.busy()) return;
    worker_.submit(request);
    submitted_ = request;
  }

  // The shown result's tables of the lobe plots' model (the sphere's when they are the same).
  const ColorTables& plot_tables() const {
    const std::optional<ColorTables>& plots = shown_->by_model[static_cast<std::size_t>(shown_->request.plot_model)];
    return plots ? *plots : shown_->tables();
  }

  // Newer parameters than the settled answer on screen are in flight (a preview on screen counts as unsettled).
  bool solving() const {
    return worker_.settling() || !submitted_ || !same_request(*submitted_, solve_request(state_));
  }

  PanelStatus panel_status() const {
    return PanelStatus{
        shown_ ? &*shown_ : nullptr,
        solving(),
        error_,
        jobs_.last_export(),
        jobs_.export_progress(),
        imgui_.unicode_labels(),
        environment_.samples(),
        environment_error_,
        jobs_.matching(),
        jobs_.match_outcome(),
        spread_status(),
        fit_job_.running() ? std::string(imgui_.unicode_labels() ? "fitting…" : "fitting...") : fit_summary_,
        fit_job_.running()};
  }

  // The scene of the shown result under the current light and view; the lobe scale (a CPU pass over the BSDF) is
  // recomputed only when the result or the light's polar angle changes.
  void update_scene() {
    if (!shown_) return;
    const double theta = degrees_to_radians(state_.light.theta_degrees);
    const double phi = degrees_to_radians(state_.light.phi_degrees);
    if (scene_generation_ != shown_->generation || scene_theta_ != theta) {  // plots' model scales the lobes
      scene_ = make_scene(plot_tables(), state_.view.view, theta, phi, 1.0, false, &scene_);
      scene_generation_ = shown_->generation;
      scene_theta_ = theta;
    }
    scene_.view = state_.view.view;
    scene_.sphere.light = light_direction(theta, phi);
    const bool environment =
        !state_.lighting.environment.empty() && environment_.loaded() == state_.lighting.environment;
    scene_.sphere.environment = environment ? std::optional<EnvironmentView>(state_.lighting.view()) : std::nullopt;
    scene_.sphere.irradiance = !environment || state_.lighting.directional ? kPi : 0.0;
    scene_.sphere.tone_map = state_.lighting.tone_map;
    if (comparing()) {  // B's lobes in A's scale, as an outline
      if (pinned_theta_ != theta) {
        pinned_lobes_ = make_scene(*pinned_tables_, ViewKind::Both, theta, phi, 1.0, false).lobes;
        pinned_theta_ = theta;
      }
      pinned_lobes_.peak = scene_.lobes.peak;
      pinned_lobes_.log_scale = scene_.lobes.log_scale;
      pinned_lobes_.decades = scene_.lobes.decades;
      pinned_lobes_.outline = true;
    }
    scene_.sphere.exposure = exposure_multiplier(state_.view);
    scene_.lobes.log_scale = state_.view.log_lobes;
  }

  // The A/B comparison: the shown material becomes B, its tables copied to the pinned slot (no solve: they are
  // what is on screen). Never a preview's tables (capped resolution): B would keep them, as no full solve of B's
  // material is requested once A changes.
  void pin_shown(PreviewState& state) {
    if (!shown_ || shown_->preview) return;
    set_pinned(state, shown_->request.material, shown_->tables(),
               renderer_.table_data(static_cast<int>(shown_->request.material.model)), "B (pinned)");
  }
  // B becomes `material`, its `tables` drawn from `textures`: the comparison's state, the pinned slot, and B's
  // estimates anew.
  void set_pinned(PreviewState& state, const ColorMaterial& material, ColorTables tables, TableTextureData textures,
                  std::string label) {
    state.comparison.pinned = material;
    state.comparison.label = std::move(label);
    pinned_tables_ = std::move(tables);
    renderer_.upload(std::move(textures), Renderer::kPinnedSlot);
    ++pin_generation_;
    environment_pinned_.reset();
    pinned_theta_ = -1.0;
  }
  // The shown material's fit for B, on a thread of its own (a second or two); pinned when it ends.
  void start_fit_pin(ShaderTarget target) {
    if (!shown_ || shown_->preview) return;
    fit_job_.start([tables = shown_->tables(), target]() -> FitPinOutcome {
      try {
        return {fitted_tables(tables, target, parallel_for_threads), target, ""};
      } catch (const std::exception& error) {
        return {std::nullopt, target, error.what()};
      }
    });
  }
  bool take_fit_pin() {
    std::optional<FitPinOutcome> outcome = fit_job_.take_outcome();
    if (!outcome) return false;
    if (!outcome->fitted) {
      fit_summary_ = "fit: " + outcome->error;
      out_ << fit_summary_ << "\n" << std::flush;
      return true;
    }
    fit_summary_ = outcome->fitted->summary;
    const char* label = outcome->target == ShaderTarget::Principled ? "B (Principled fit)" : "B (OpenPBR fit)";
    ColorTables& tables = outcome->fitted->tables;
    TableTextureData textures = make_table_textures(tables);
    const ColorMaterial material = tables.material;
    set_pinned(state_, material, std::move(tables), std::move(textures), label);
    out_ << "pinned " << label << ": " << fit_summary_ << "\n" << std::flush;
    return true;
  }

  void unpin(PreviewState& state) {
    state.comparison.pinned.reset();
    pinned_tables_.reset();
    environment_pinned_.reset();
  }
  bool comparing() const {
    return state_.comparison.pinned && pinned_tables_ && shown_ && scene_.view != ViewKind::Compare;
  }
  SurfaceParams pinned_surface() const {
    const Material& pinned = state_.comparison.pinned->layer;
    return {pinned.eta, pinned.sigma, pinned.microfacet};
  }

  // Loads a newly chosen environment and refines the sphere's estimate under it for a slice of this frame: a few
  // milliseconds while something moves, more when the window is idle. Returns true while it is still refining.
  bool refine_environment(const PreviewLayout& layout, std::array<float, 2> scale, std::array<int, 2> framebuffer,
                          bool activity) {
    const std::string& source = state_.lighting.environment;
    if (source.empty() || !shown_ || layout.sphere.empty() || scene_.view == ViewKind::Compare) {
      environment_.reset();
      environment_pinned_.reset();
      return false;
    }
    if (source != environment_.loaded() && source != failed_environment_) {
      environment_error_ = environment_.load(renderer_, source);
      failed_environment_ = environment_error_.empty() ? "" : source;
      environment_pinned_.reset();  // its estimate was of the previous environment
      if (!environment_error_.empty()) out_ << "environment: " << environment_error_ << "\n" << std::flush;
      update_scene();
    }
    if (environment_.loaded() != source) return false;
    const Viewport sphere = to_viewport(layout.sphere, scale, framebuffer[1]);
    const EnvironmentView view = state_.lighting.view();
    const EnvironmentPreview::Key key{shown_->generation, static_cast<int>(shown_->request.material.model),
                                      view.rotation,      view.scale,
                                      sphere.width,       sphere.height};
    const double budget = activity ? 0.006 : 0.03;
    if (!comparing()) return environment_.refine(renderer_, key, view, scene_.surface, budget);
    // The A/B comparison: B's estimate shares the slice.
    const EnvironmentPreview::Key pinned{pin_generation_, Renderer::kPinnedSlot, view.rotation,
                                         view.scale,      sphere.width,          sphere.height};
    const bool a = environment_.refine(renderer_, key, view, scene_.surface, 0.5 * budget);
    const bool b = environment_pinned_.refine(renderer_, pinned, view, pinned_surface(), 0.5 * budget);
    return a || b;
  }

  void draw_views(const PreviewLayout& layout, std::array<float, 2> scale, std::array<int, 2> framebuffer) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebuffer[0], framebuffer[1]);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glClearColor(0.02f, 0.02f, 0.025f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!shown_) return;
    const SolveRequest& shown = shown_->request;
    if (!layout.sphere.empty()) {
      const Viewport sphere = to_viewport(layout.sphere, scale, framebuffer[1]);
      const int slot = static_cast<int>(shown.material.model);
      if (comparing()) {
        renderer_.draw_split_sphere(scene_.sphere, {scene_.surface, pinned_surface()}, {slot, Renderer::kPinnedSlot},
                                    {environment_.accumulation(), environment_pinned_.accumulation()}, sphere,
                                    state_.comparison.split);
      } else {
        renderer_.draw_sphere(scene_.sphere, scene_.surface, sphere, slot, environment_.accumulation());
      }
    }
    if (!layout.plots.empty()) {
      const Viewport plots = to_viewport(layout.plots, scale, framebuffer[1]);
      renderer_.draw_lobes(scene_.lobes, scene_.surface, plots, static_cast<int>(shown.plot_model));
      if (comparing()) renderer_.draw_lobes(pinned_lobes_, pinned_surface(), plots, Renderer::kPinnedSlot);
    }
    if (scene_.view == ViewKind::Compare && shown_->request.compare) {
      for (std::size_t k = 0; k < kCompareSlots.size(); ++k) {
        renderer_.draw_sphere(scene_.sphere, scene_.surface, to_viewport(layout.compare[k], scale, framebuffer[1]),
                              kCompareSlots[k]);
      }
    }
  }

  // The Export buttons (and the test hook's exports): the shown material, what the window draws, to the screenshot
  // path with the format's extension.
  void export_shown(ExportFormat format, const std::string& requested = "") {
    const bool shown = shown_ && shown_->error.empty();
    jobs_.start_export(format, shown ? &shown_->tables() : nullptr,
                       requested.empty() ? state_.export_options.path : requested);
  }

  // Saves a region of the back buffer; failures are shown in the panel (and thrown in capture mode).
  void export_picture(const Viewport& region, const std::string& path) {
    try {
      const SavedScreenshot saved =
          save_screenshot(region, path, {picture_metadata(shown_material(), drawing_settings(state_, comparing()))});
      out_ << "wrote " << saved.path << " (" << saved.width << "x" << saved.height << ")\n" << std::flush;
      jobs_.note_export("saved " + saved.path + " (" + std::to_string(saved.width) + "x" +
                        std::to_string(saved.height) + ")");
    } catch (const std::exception& error) {
      if (capture_path_) throw;
      jobs_.note_export(error.what());
    }
  }

  Edit current_edit() const { return Edit{state_.material, state_.light}; }

  void step_history(const std::optional<Edit>& edit) {
    if (!edit) return;
    state_.material = edit->material;
    state_.light = edit->light;
  }

  FileSectionInput file_section_input() const {
    FileSectionInput input = files_.section_input(state_.material);
    input.undo_steps = history_.undo_steps();
    input.redo_steps = history_.redo_steps();
    return input;
  }

  void run_file_command(const FileCommand& command) {
    if (files_.run(command, state_.material)) window_.request_close();
  }

  // The test hook's actions on the previewer (TestActionTarget, test_action_script.h).
  PreviewState& state() override { return state_; }
  void print_title() override {
    out_ << "title: " << window_title(files_.session(), state_.material, false) << "\n" << std::flush;
  }
  void start_export(ExportFormat format, const std::string& path) override { export_shown(format, path); }
  void start_match(const std::array<double, 3>& srgb) override { jobs_.start_match(state_.material, srgb); }
  void print_memory() override {
    const auto kilobytes = [](std::optional<std::size_t> bytes) {
      return bytes ? std::to_string(*bytes / 1024) + " kB" : std::string("unknown");
    };
    out_ << "memory: resident " << kilobytes(resident_memory_bytes()) << ", heap in use "
         << kilobytes(heap_in_use_bytes()) << ", solve cache " << kilobytes(worker_.stats().cache_bytes) << "\n"
         << std::flush;
  }
  void pin() override { pin_shown(state_); }
  void pin_fit(ShaderTarget target) override { start_fit_pin(target); }
  void unpin() override { unpin(state_); }

  // The material of the picture on screen (the shown result's; the sliders may be ahead of it).
  MaterialDocument shown_material() const {
    MaterialDocument document = material_document(shown_ ? shown_->request.material : state_.material);
    document.name = files_.session().name;
    document.description = files_.session().description;
    return document;
  }

  // --capture: once the shown result answers the final parameters and a few frames have shown it, save the whole
  // window through the same export path as the S key, and finish.
  void capture_if_ready(std::array<int, 2> framebuffer) {
    if (!capture_path_ || !script_.finished() || jobs_.running() || spread_job_.running()) return;
    if (spread_wanted() && !for_shown(spread_material_)) {
      return;  // the translucency of the shown material is still to come
    }
    const bool final_result = submitted_ && !worker_.settling();
    if (final_result && !error_.empty()) throw std::runtime_error(error_);
    if (!final_result || !shown_ || shown_->preview || !same_request(shown_->request, *submitted_)) return;
    // Under an environment, the estimate has its --samples (and it belongs to what is shown); a capture always
    // shows the quarter-side estimate, never the coarse one of the first frame after a change.
    if (!state_.lighting.environment.empty()) {
      if (!environment_error_.empty()) throw std::runtime_error(environment_error_);
      const int wanted =
          std::clamp(capture_samples_, EnvironmentPreview::kFineShownFrom, EnvironmentPreview::kMaxSamples);
      if (environment_.samples() < wanted || (comparing() && environment_pinned_.samples() < wanted) ||
          !scene_.sphere.environment) {
        return;
      }
    }
    if (++settled_frames_ < kCaptureSettleFrames) return;
    export_picture(Viewport{0, 0, framebuffer[0], framebuffer[1]}, *capture_path_);
    captured_ = true;
  }

  std::ostream& out_;
  std::optional<std::string> capture_path_;
  GlfwWindow window_;
  ImGuiSession imgui_;
  Renderer renderer_;
  PreviewState state_;
  std::optional<SolveResult> shown_;       // on screen: its tables are uploaded to renderer_
  std::optional<SolveRequest> submitted_;  // the newest request given to the worker
  std::string error_;                      // the newest result's error, if it failed
  Scene scene_;
  std::uint64_t scene_generation_ = 0;
  double scene_theta_ = -1.0;
  int eager_frames_ = kEagerFrames;
  int settled_frames_ = 0;
  bool captured_ = false;
  bool resting_ = false;  // the window has come to rest since the last activity (rest_if_idle)
  int quiet_frames_ = 0;  // frames since the last input or result
  EditHistory history_;
  MaterialFiles files_;
  TestActionScript script_;  // --test-actions
  EnvironmentPreview environment_;
  EnvironmentPreview environment_pinned_;     // B's estimate in the A/B comparison
  std::optional<ColorTables> pinned_tables_;  // B's tables (its textures are in Renderer::kPinnedSlot)
  struct FitPinOutcome {
    std::optional<FittedTables> fitted;
    ShaderTarget target;
    std::string error;
  };
  OneShotJob<FitPinOutcome> fit_job_;         // the fit for B (B: Principled fit, B: OpenPBR fit)
  std::string fit_summary_;                   // the last fit's summary or error, for the panel
  std::uint64_t pin_generation_ = 0;          // counts pins: B's estimate restarts with each
  LobeView pinned_lobes_;                     // B's lobes, drawn as an outline in A's scale
  double pinned_theta_ = -1.0;                // the light angle pinned_lobes_ was made for
  std::string environment_error_;   // why the chosen environment could not be loaded
  std::string failed_environment_;  // that source, not retried until another is chosen
  int capture_samples_ = 0;         // --capture under an environment waits for this many samples per pixel
  BackgroundJobs jobs_;  // the exports and "Match colour..."
  SpreadJob spread_job_;                           // the translucency's profile
  std::optional<ColorMaterial> spread_requested_;  // the material the last started profile is for
  std::optional<ColorMaterial> spread_material_;   // the material of the last finished one
  std::optional<SpreadProfile> spread_profile_;    // its profile; unset: it has none (spread_note_ says why)
  std::string spread_note_;
  double spread_radius_ = -1.0;  // the sphere radius of the uploaded texture; -1: none uploaded for this profile
  SolveWorker worker_;  // last: destroyed (joined) first, while GLFW, which it wakes, is still initialized
};

}  // namespace

int run_previewer(const WindowOptions& options, std::ostream& out) {
  Previewer previewer(options, out);
  return previewer.run();
}

}  // namespace skinlayer
