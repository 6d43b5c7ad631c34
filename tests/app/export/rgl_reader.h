// A reader of RGL measured-BSDF tensor files written for the tests from the format's description alone (it shares no
// code with skinlayer's writer): a strict parse of the container, and the BRDF, its sampling density and its sampling
// as pbrt-v4's MeasuredBxDF (f, PDF, Sample_f) and Mitsuba 3's `measured` plugin (eval) compute them. With m the
// half vector and xi the inverse of the VNDF warp at m,
//   pbrt-v4:   f = max(0, S(xi)) D~(u_m) / (4 sigma~(u_o) cos theta_i)
//   Mitsuba 3: f cos theta_i = S(xi) D~(u_m) / (4 sigma~(u_o))   (jacobian = 1; S not clamped)
// with S the `rgb` channel or the `spectra` value at a wavelength (linear between the `wavelengths`, clamped).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace skinlayer::test {

struct RglField {
  std::uint8_t dtype = 0;  // 1 uint8, 10 float32
  std::vector<std::uint64_t> shape;
  std::vector<float> floats;        // dtype 10
  std::vector<std::uint8_t> bytes;  // dtype 1
};

struct RglFile {
  std::map<std::string, RglField> fields;
  const RglField& at(const std::string& name) const;
  bool spectral() const { return fields.contains("spectra"); }
};

// Throws std::runtime_error naming what is wrong: magic, version, a dtype other than uint8 or float32, an offset
// that is not 8-byte aligned or runs past the end, a repeated field, or a missing or misshapen BSDF field (the rgb
// form's `rgb`, or the spectral form's `spectra` with its `wavelengths`).
RglFile read_rgl(const std::filesystem::path& path);

using Direction = std::array<double, 3>;  // a unit vector, z the normal

// The channel a value is read from: the rgb form's channel 0-2, or the spectral form at a wavelength in nm.
struct RglChannel {
  int rgb = 0;
  double wavelength_nm = 0.0;
};

// The file seen from one camera direction wo: the VNDF and luminance slices blended at its angles once, so that
// many light directions are cheap.
class RglCamera {
 public:
  RglCamera(const RglFile& file, const Direction& wo);
  ~RglCamera();
  RglCamera(const RglCamera&) = delete;
  RglCamera& operator=(const RglCamera&) = delete;

  // The BRDF in 1/sr toward the light wi, as pbrt-v4's f evaluates it; zero unless both are above the surface.
  double brdf(const Direction& wi, const RglChannel& channel) const;
  // The same as Mitsuba 3 computes it: its eval (f cos theta_i) divided by cos theta_i.
  double brdf_mitsuba(const Direction& wi, const RglChannel& channel) const;
  // pbrt-v4's PDF: the density in 1/sr with which Sample_f picks wi (luminance, then the VNDF warp, then the mirror
  // reflection about the half vector).
  double pdf(const Direction& wi) const;
  // pbrt-v4's Sample_f for uniform numbers (u1, u2): wi and its density; none when the mirror leaves the hemisphere.
  struct Sample {
    Direction wi;
    double pdf = 0.0;
  };
  std::optional<Sample> sample(double u1, double u2) const;

 private:
  struct Tables;
  const RglFile& file_;
  Direction wo_;
  std::unique_ptr<Tables> tables_;
};

// One pair, as pbrt-v4 reads the rgb form's three channels.
std::array<double, 3> rgl_brdf_rgb(const RglFile& file, const Direction& wo, const Direction& wi);

}  // namespace skinlayer::test
