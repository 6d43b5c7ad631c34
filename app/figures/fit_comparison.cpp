#include "app/figures/fit_comparison.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "app/figures/canvas.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "core/color/luminance.h"
#include "core/color/spectral_color.h"
#include "core/conventions.h"

namespace skinlayer::figures {
namespace {

using Rgb = Eigen::Array3d;

constexpr double kMapRange = 0.25;  // the map saturates at +-25%

// A world direction in the frame of the normal n (any tangent: the BSDFs are isotropic).
Vec3 local(const Vec3& n, const Vec3& w) {
  const Vec3 t = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 b = n.cross(t);
  return {t.dot(w), b.dot(w), n.dot(w)};
}

std::uint8_t byte(double value) { return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(value, 0.0, 1.0))); }

void put(Image& image, int x, int y, const Rgb& display) {
  const std::size_t at = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + x);
  for (int c = 0; c < 3; ++c) image.rgba[at + static_cast<std::size_t>(c)] = byte(display(c));
  image.rgba[at + 3] = 255;
}

Rgb shown(const Rgb& radiance) {
  Rgb out;
  for (int c = 0; c < 3; ++c) out(c) = srgb_encode(1.0 - std::exp(-radiance(c)));
  return out;
}

}  // namespace

FitComparison draw_fit_comparison(const MaterialDocument& document, const FittedBrdf& fitted,
                                  const std::string& fitted_label, const Font& font, int sphere_size,
                                  const ParallelFor& parallel_for) {
  const int n = sphere_size;
  const Vec3 view = Vec3::UnitZ(), light = Vec3(-std::sin(kPi / 4), 0.0, std::cos(kPi / 4));
  struct Pixel {
    int x, y;
  };
  std::vector<Pixel> pixels;
  std::vector<Vec3> lights, views;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double px = (x + 0.5) / n * 2.0 - 1.0, py = 1.0 - (y + 0.5) / n * 2.0;
      const double r2 = px * px + py * py;
      if (r2 >= 0.98) continue;
      const Vec3 normal(px, py, std::sqrt(1.0 - r2));
      const Vec3 l = local(normal, light), v = local(normal, view);
      if (l.z() <= 0.0) continue;
      pixels.push_back({x, y});
      lights.push_back(l);
      views.push_back(v);
    }
  }
  const std::vector<Rgb> brdf =
      brdf_rgb(solve_document(document, SubsurfaceModel::Stam, parallel_for), lights, views, parallel_for);
  const std::size_t count = pixels.size();
  std::vector<Rgb> exact(count), fit(count);
  double brightest = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    exact[k] = kPi * brdf[k] * lights[k].z();
    fit[k] = kPi * fitted(lights[k], views[k]);
    brightest = std::max(brightest, luminance(exact[k](0), exact[k](1), exact[k](2)));
  }

  const double u = n / 256.0;
  const int title = static_cast<int>(40 * u), label = static_cast<int>(34 * u);
  Canvas canvas(3 * n, title + n + label, {255, 255, 255, 255});
  Image spheres{3 * n, n, std::vector<std::uint8_t>(static_cast<std::size_t>(3 * n * n) * 4, 0)};
  for (std::size_t k = 0; k < spheres.rgba.size(); k += 4) {
    spheres.rgba[k] = spheres.rgba[k + 1] = spheres.rgba[k + 2] = 24;
    spheres.rgba[k + 3] = 255;
  }
  FitComparison result;
  double squares = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const Pixel& p = pixels[k];
    put(spheres, p.x, p.y, shown(exact[k]));
    put(spheres, n + p.x, p.y, shown(fit[k]));
    const double y_exact = luminance(exact[k](0), exact[k](1), exact[k](2));
    const double y_fit = luminance(fit[k](0), fit[k](1), fit[k](2));
    Rgb map = Rgb::Constant(0.35);
    if (y_exact > 0.01 * brightest) {
      const double relative = y_fit / y_exact - 1.0, t = std::clamp(relative / kMapRange, -1.0, 1.0);
      map = t >= 0.0 ? Rgb(1.0, 1.0 - t, 1.0 - t) : Rgb(1.0 + t, 1.0 + t, 1.0);
      squares += relative * relative;
      ++result.lit_pixels;
    }
    put(spheres, 2 * n + p.x, p.y, map);
  }
  result.rms_difference = result.lit_pixels > 0 ? std::sqrt(squares / result.lit_pixels) : 0.0;
  canvas.blit(spheres, 0, title);
  const std::string name = document.name.empty() ? "the material" : document.name;
  canvas.text(font, name + ": exact | " + fitted_label + " | difference", {1.5 * n, 27 * u}, 17 * u, {30, 30, 30, 255},
              Align::Center);
  char map_label[96];
  std::snprintf(map_label, sizeof map_label, "blue -25%%, red +25%%; RMS %.1f%%", 100.0 * result.rms_difference);
  const Rgba dark{30, 30, 30, 255};
  canvas.text(font, "skinlayer", {0.5 * n, title + n + 24 * u}, 14 * u, dark, Align::Center);
  canvas.text(font, fitted_label, {1.5 * n, title + n + 24 * u}, 14 * u, dark, Align::Center);
  canvas.text(font, map_label, {2.5 * n, title + n + 24 * u}, 14 * u, dark, Align::Center);
  result.image = canvas.image();
  return result;
}

}  // namespace skinlayer::figures
