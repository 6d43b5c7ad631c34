#include "app/figures/model_spheres.h"

#include "app/figures/canvas.h"
#include "app/gl/osmesa_context.h"
#include "app/process/parallel_for.h"
#include "app/render/render_target.h"
#include "app/render/renderer.h"
#include "app/render/scene.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"
#include "app/solution/sphere_spread.h"
#include "core/conventions.h"

namespace skinlayer::figures {

Image draw_model_spheres(const FigureSpec& spec, const Font& font, int sphere_size) {
  const double u = sphere_size / 320.0;
  const int title_height = static_cast<int>(64 * u), label_height = static_cast<int>(40 * u);
  const int width = sphere_size * static_cast<int>(spec.curves.size());
  Canvas canvas(width, title_height + sphere_size + label_height, {255, 255, 255, 255});
  canvas.text(font, spec.title, {width / 2.0, 28 * u}, 21 * u, {30, 30, 30, 255}, Align::Center);
  canvas.text(font, spec.subtitle, {width / 2.0, 52 * u}, 13 * u, {110, 110, 110, 255}, Align::Center);

  const double light_theta = degrees_to_radians(spec.light_theta_deg), light_phi = degrees_to_radians(180.0);
  gl::OsmesaContext context(sphere_size, sphere_size);
  Renderer renderer;
  RenderTarget target(sphere_size, sphere_size, PixelFormat::Rgba8);
  for (std::size_t k = 0; k < spec.curves.size(); ++k) {
    const FigureCurve& curve = spec.curves[k];
    const ColorTables tables = solve_color(
        ColorMaterial{curve.params.material(), curve.albedo_rgb, {}, curve.model, curve.skin}, light_theta);
    renderer.upload(make_table_textures(tables));
    Scene scene = make_scene(tables, ViewKind::Sphere, light_theta, light_phi, 1.0, false);
    if (spec.sphere_radius_mm > 0.0) {  // the translucency (app/solution/sphere_spread.h)
      // A skin's on its 7 preview wavelengths, as the previewer's: a figure of three skins in seconds.
      const SpreadProfile profile = spread_profile(material_document(tables.material), true, parallel_for_threads);
      renderer.upload_spread(spread_texture(profile, spec.sphere_radius_mm));
      scene.sphere.spread = true;
    }
    target.bind();
    draw_scene(renderer, scene, sphere_size, sphere_size);
    RenderTarget::unbind();
    const int x = static_cast<int>(k) * sphere_size;
    canvas.blit(Image{sphere_size, sphere_size, target.read_rgba8()}, x, title_height);
    canvas.text(font, curve.label, {x + sphere_size / 2.0, title_height + sphere_size + 26 * u}, 17 * u,
                {30, 30, 30, 255}, Align::Center);
  }
  return canvas.image();
}

}  // namespace skinlayer::figures
