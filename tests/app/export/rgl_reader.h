// A reader of RGL measured-BSDF tensor files written for the tests from the format's description alone (it shares no
// code with skinlayer's writer): a strict parse of the container, and the BRDF as pbrt-v4's MeasuredBxDF::f
// reconstructs it (f = S(xi) D~(u_m) / (4 sigma~(u_o) cos theta_i), xi the inverse of the VNDF warp at the half
// vector), in the rgb form's three channels.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
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
};

// Throws std::runtime_error naming what is wrong: magic, version, a dtype other than uint8 or float32, an offset
// that is not 8-byte aligned or runs past the end, a repeated field, or a missing or misshapen BSDF field.
RglFile read_rgl(const std::filesystem::path& path);

// The rgb form's BRDF in 1/sr for a camera direction wo and a light direction wi (unit vectors, z the normal), as
// pbrt-v4 evaluates it; zero unless both are above the surface.
std::array<double, 3> rgl_brdf(const RglFile& file, const std::array<double, 3>& wo, const std::array<double, 3>& wi);

}  // namespace skinlayer::test
