// `skinlayer export --format merl` read back by a reader written here from the format's description
// (docs/exchange-formats.md §2), sharing no code with the writer: the exact size and header, the
// channel-major float64 body, the Rusinkiewicz lookup a MERL reader does, and every sampled bin's value against
// `skinlayer eval` at that bin's centre (float64 stores it exactly: agreement to rounding). Bins below the horizon
// hold a negative value.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kBins = 90 * 90 * 180;
constexpr std::array<double, 3> kScale = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};  // what a reader multiplies by

struct V {
  double x, y, z;
};
V normalize(V v) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / n, v.y / n, v.z / n};
}
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// Rotation of v by angle a about the z axis and about the y axis.
V rotate_z(V v, double a) { return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y, v.z}; }
V rotate_y(V v, double a) { return {std::cos(a) * v.x + std::sin(a) * v.z, v.y, -std::sin(a) * v.x + std::cos(a) * v.z}; }

// A MERL reader's lookup (BRDFRead.cpp's recipe): the bin index of a direction pair, both away from the surface.
std::size_t merl_index(V wi, V wo) {
  const V h = normalize({wi.x + wo.x, wi.y + wo.y, wi.z + wo.z});
  const double theta_h = std::acos(std::clamp(h.z, -1.0, 1.0));
  const double phi_h = std::atan2(h.y, h.x);
  const V d = rotate_y(rotate_z(wi, -phi_h), -theta_h);
  const double theta_d = std::acos(std::clamp(d.z, -1.0, 1.0));
  double phi_d = std::atan2(d.y, d.x);
  if (phi_d < 0.0) phi_d += kPi;
  const int th = theta_h <= 0.0 ? 0 : std::clamp(static_cast<int>(std::sqrt(theta_h / (kPi / 2)) * 90.0), 0, 89);
  const int td = std::clamp(static_cast<int>(theta_d / (kPi / 2) * 90.0), 0, 89);
  const int pd = std::clamp(static_cast<int>(phi_d / kPi * 180.0), 0, 179);
  return static_cast<std::size_t>(pd) + 180 * static_cast<std::size_t>(td) + 16200 * static_cast<std::size_t>(th);
}

struct Merl {
  std::vector<double> values;  // 3 x kBins, channel-major, as stored
};

Merl read_merl(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes.size(), 12u + 3u * kBins * 8u) << "a MERL file is exactly 34,992,012 bytes";
  std::int32_t dims[3];
  std::memcpy(dims, bytes.data(), sizeof dims);
  EXPECT_EQ(dims[0], 90);
  EXPECT_EQ(dims[1], 90);
  EXPECT_EQ(dims[2], 180);
  Merl merl;
  merl.values.resize(3 * kBins);
  if (bytes.size() == 12u + 3u * kBins * 8u) std::memcpy(merl.values.data(), bytes.data() + 12, 3 * kBins * 8);
  return merl;
}

// One bin's centre as a writer samples it, built here with rotations rather than the writer's closed form.
std::pair<V, V> bin_centre(int th, int td, int pd) {
  const double x = (th + 0.5) / 90.0;
  const double theta_h = kPi / 2 * x * x, theta_d = kPi / 2 * (td + 0.5) / 90.0, phi_d = kPi * (pd + 0.5) / 180.0;
  const V d = {std::sin(theta_d) * std::cos(phi_d), std::sin(theta_d) * std::sin(phi_d), std::cos(theta_d)};
  const V wi = rotate_y(d, theta_h);
  const V h = rotate_y({0.0, 0.0, 1.0}, theta_h);
  const double c = 2.0 * dot(wi, h);
  return {wi, {c * h.x - wi.x, c * h.y - wi.y, c * h.z - wi.z}};
}

class MerlExport : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = fs::temp_directory_path() / ("skinlayer_merl_" + std::to_string(::getpid()) + ".binary");
  }
  void TearDown() override { fs::remove(path_); }
  fs::path path_;
};

TEST_F(MerlExport, EveryBinIsTheBrdfAtItsCentreAndAReaderFindsIt) {
  const std::vector<std::string> material = {"--preset", "paper-skin", "--sigma", "0.3"};
  std::vector<std::string> command = {"export", "--format", "merl", "-o", path_.string()};
  command.insert(command.end(), material.begin(), material.end());
  const ProcessResult exported = run_skinlayer(command);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.err.find("theta_h rows"), std::string::npos) << "progress on stderr";
  const Merl merl = read_merl(path_);
  ASSERT_EQ(merl.values.size(), 3 * kBins);

  std::mt19937 random(7);
  std::string rows = "theta_i,theta_o,phi\n";
  std::vector<std::size_t> sampled;
  int below = 0;
  for (int k = 0; k < 3000 && sampled.size() < 600; ++k) {
    const int th = static_cast<int>(random() % 90), td = static_cast<int>(random() % 90);
    const int pd = static_cast<int>(random() % 180);
    const auto [wi, wo] = bin_centre(th, td, pd);
    const std::size_t index = static_cast<std::size_t>(pd) + 180 * static_cast<std::size_t>(td) + 16200 * th;
    if (wi.z <= 0.0 || wo.z <= 0.0) {
      for (int c = 0; c < 3; ++c) EXPECT_LT(merl.values[c * kBins + index], 0.0) << "below the horizon";
      ++below;
      continue;
    }
    EXPECT_EQ(merl_index(wi, wo), index) << "a reader's lookup of the bin centre finds the bin";
    const double phi = std::atan2(wo.y, wo.x) - std::atan2(wi.y, wi.x);
    char row[128];
    std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g\n", std::acos(wi.z) * 180.0 / kPi,
                  std::acos(wo.z) * 180.0 / kPi, phi * 180.0 / kPi);
    rows += row;
    sampled.push_back(index);
  }
  EXPECT_GT(below, 0);
  ASSERT_GE(sampled.size(), 500u);
  // eval solves one channel: each channel's albedo in turn (paper-skin's RGB albedo, 0.95 / 0.7 / 0.55).
  const std::array<const char*, 3> albedos = {"0.95", "0.7", "0.55"};
  for (int c = 0; c < 3; ++c) {
    std::vector<std::string> eval = {"eval", "--albedo", albedos[c]};
    eval.insert(eval.end(), material.begin(), material.end());
    const ProcessResult evaluated = run_skinlayer(eval, rows);
    ASSERT_EQ(evaluated.exit_code, 0) << evaluated.err;
    std::istringstream lines(evaluated.out);
    std::string line;
    std::getline(lines, line);  // header: theta_i,theta_o,phi,brdf_surface,brdf_subsurface,brdf,btdf
    double worst = 0.0;
    for (const std::size_t index : sampled) {
      ASSERT_TRUE(std::getline(lines, line));
      std::vector<double> fields;
      std::istringstream split(line);
      std::string field;
      while (std::getline(split, field, ',')) fields.push_back(std::strtod(field.c_str(), nullptr));
      const double expected = fields.at(5);
      const double stored = merl.values[c * kBins + index] * kScale[c];
      EXPECT_GE(stored, 0.0);
      worst = std::max(worst, std::abs(stored - expected) / std::max(expected, 1e-12));
    }
    EXPECT_LT(worst, 1e-9) << "channel " << c;
  }
}

TEST_F(MerlExport, BadRequestsAreOneLineAndLeaveNoFile) {
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "-o", path_.string()}), 2, {"--format"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"export", "--format", "obj", "-o", path_.string()}), 2, {"obj", "merl"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "merl"}), 2, {"-o"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "merl", "--g", "2", "-o", path_.string()}), 2,
                                   {"g = 2"}));
  EXPECT_FALSE(fs::exists(path_));
  const ProcessResult unwritable = run_skinlayer({"export", "--format", "merl", "-o", "/nonexistent/dir/x.binary"});
  EXPECT_TRUE(failed_with_one_line(unwritable, 1, {"/nonexistent/dir/x.binary"}));
}

}  // namespace
}  // namespace skinlayer::test
