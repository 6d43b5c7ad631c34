// The SCATFUN v1 reader (scatfun_reader.h) alone, on byte buffers built here by hand from the header layout of
// docs/exchange-formats.md §1: every structural rule it enforces, the CDF check, and the pbrt-v3-style
// evaluation against hand-computed numbers.
#include "tests/app/export/scatfun_reader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace skinlayer::test {
namespace {

constexpr double kTol = 1e-6;  // float32 coefficients evaluated in double

// A SCATFUN v1 file under construction; bytes() lays it out little-endian, 64-byte header then the body.
struct Builder {
  char version = 1;
  std::uint32_t flags = 1, m_max = 3, n_channels = 1, n_bases = 1, n_parameters = 0, n_parameter_values = 0;
  float eta = 1.5f;
  float alpha[2] = {0.1f, 0.2f};
  std::vector<float> mu;
  std::vector<float> cdf;  // empty: a running trapezoid sum of each row's a0 (starts at 0, never decreases)
  std::vector<std::uint32_t> offset, length;
  std::vector<float> coeffs;
  std::string metadata = R"({"writer":"test"})";

  explicit Builder(std::vector<float> nodes, std::uint32_t channels = 1)
      : n_channels(channels),
        mu(std::move(nodes)),
        offset(mu.size() * mu.size(), 0),
        length(mu.size() * mu.size(), 0) {}

  // Entry (row, col) gets one block of coefficients per channel, appended to coeffs.
  void set(std::size_t row, std::size_t col, const std::vector<std::vector<float>>& blocks) {
    const std::size_t e = row * mu.size() + col;
    offset[e] = static_cast<std::uint32_t>(coeffs.size());
    length[e] = static_cast<std::uint32_t>(blocks.front().size());
    for (const auto& block : blocks) coeffs.insert(coeffs.end(), block.begin(), block.end());
  }

  std::vector<float> default_cdf() const {
    const std::size_t n = mu.size();
    std::vector<float> out(n * n, 0.0f);
    for (std::size_t row = 0; row < n; ++row) {
      auto a0 = [&](std::size_t col) {
        const std::size_t e = row * n + col;
        return length[e] > 0 ? double{coeffs[offset[e]]} : 0.0;
      };
      double sum = 0.0;
      for (std::size_t k = 0; k + 1 < n; ++k) {
        sum += (double{mu[k + 1]} - mu[k]) * (a0(k) + a0(k + 1)) / 2;
        out[row * n + k + 1] = static_cast<float>(sum);
      }
    }
    return out;
  }

  std::string bytes() const {
    std::string out;
    auto u32 = [&](std::uint32_t v) {
      for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
    };
    auto f32 = [&](float v) {
      std::uint32_t bits;
      std::memcpy(&bits, &v, 4);
      u32(bits);
    };
    out = "SCATFUN";
    out.push_back(version);
    for (std::uint32_t v :
         {flags, static_cast<std::uint32_t>(mu.size()), static_cast<std::uint32_t>(coeffs.size()), m_max, n_channels,
          n_bases, static_cast<std::uint32_t>(metadata.size()), n_parameters, n_parameter_values}) {
      u32(v);
    }
    for (float v : {eta, alpha[0], alpha[1], 0.0f, 0.0f}) f32(v);
    for (float v : mu) f32(v);
    for (float v : cdf.empty() ? default_cdf() : cdf) f32(v);
    for (std::size_t e = 0; e < offset.size(); ++e) {
      u32(offset[e]);
      u32(length[e]);
    }
    for (float v : coeffs) f32(v);
    out += metadata;
    return out;
  }
};

const std::vector<float> kSixNodes = {-1.0f, -0.5f, 0.0f, 0.0f, 0.5f, 1.0f};

// A small valid grey file: a few entries of length 1 to 3, none on the zero nodes (indices 2 and 3).
Builder small_grey() {
  Builder b(kSixNodes);
  b.set(4, 1, {{0.3f, 0.1f}});           // muO 0.5, muI -0.5
  b.set(5, 1, {{0.25f, 0.1f, 0.05f}});   // muO 1, muI -0.5
  b.set(1, 4, {{0.15f, 0.05f, 0.02f}});  // muO -0.5, muI 0.5
  b.set(0, 5, {{0.05f, 0.02f}});
  return b;
}

::testing::AssertionResult throws_naming(const std::string& bytes, std::string_view rule) {
  try {
    parse_scatfun(bytes);
  } catch (const std::runtime_error& error) {
    if (std::string_view(error.what()).find(rule) != std::string_view::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "the message \"" << error.what() << "\" does not name \"" << rule << "\"";
  }
  return ::testing::AssertionFailure() << "no exception; expected one naming \"" << rule << "\"";
}

// Directions in pbrt's frame for a propagation cosine muI of the incident light (-wi), a cosine muO of wo, and the
// cosine of their azimuth difference.
std::array<double, 3> eval(const ScatfunFile& file, double mu_i, double mu_o, double cos_phi, bool radiance = true) {
  const double si = std::sqrt(1.0 - mu_i * mu_i), so = std::sqrt(1.0 - mu_o * mu_o);
  const double phi = std::acos(cos_phi);
  const std::array<double, 3> wi = {-si, 0.0, -mu_i};
  const std::array<double, 3> wo = {so * std::cos(phi), so * std::sin(phi), mu_o};
  return pbrt_fourier_f(file, wo, wi, radiance);
}

void expect_grey(const std::array<double, 3>& rgb, double value) {
  EXPECT_NEAR(rgb[0], value, kTol);
  EXPECT_NEAR(rgb[1], value, kTol);
  EXPECT_NEAR(rgb[2], value, kTol);
}

// --- structure ---

TEST(ScatfunReader, ValidGreyFileParses) {
  const Builder b = small_grey();
  const ScatfunFile file = parse_scatfun(b.bytes());
  EXPECT_EQ(file.flags, 1u);
  EXPECT_EQ(file.n_mu, 6u);
  EXPECT_EQ(file.n_coeffs, 10u);
  EXPECT_EQ(file.m_max, 3u);
  EXPECT_EQ(file.n_channels, 1u);
  EXPECT_EQ(file.n_bases, 1u);
  EXPECT_EQ(file.n_metadata_bytes, b.metadata.size());
  EXPECT_EQ(file.n_parameters, 0u);
  EXPECT_EQ(file.n_parameter_values, 0u);
  EXPECT_EQ(file.eta, 1.5f);
  EXPECT_EQ(file.alpha[0], 0.1f);
  EXPECT_EQ(file.alpha[1], 0.2f);
  EXPECT_EQ(file.mu, kSixNodes);
  EXPECT_EQ(file.cdf, b.default_cdf());
  EXPECT_EQ(file.offset, b.offset);
  EXPECT_EQ(file.length, b.length);
  EXPECT_EQ(file.coeffs, b.coeffs);
  EXPECT_EQ(file.metadata, b.metadata);
  EXPECT_EQ(file.length[5 * 6 + 1], 3u);
  EXPECT_EQ(file.coeffs[file.offset[5 * 6 + 1] + 2], 0.05f);
}

TEST(ScatfunReader, ReadsAFile) {
  const Builder b = small_grey();
  const auto path = std::filesystem::temp_directory_path() / ("scatfun_reader_test_" + std::to_string(getpid()));
  {
    std::ofstream out(path, std::ios::binary);
    const std::string bytes = b.bytes();
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  const ScatfunFile file = read_scatfun(path);
  std::filesystem::remove(path);
  EXPECT_EQ(file.coeffs, b.coeffs);
  EXPECT_EQ(file.metadata, b.metadata);
  EXPECT_THROW(read_scatfun(path), std::runtime_error);
}

TEST(ScatfunReader, GridWithoutDoubledZeroIsAccepted) {
  Builder b({-1.0f, -0.5f, 0.0f, 0.5f, 1.0f});
  b.set(3, 1, {{0.3f}});
  EXPECT_NO_THROW(parse_scatfun(b.bytes()));
}

TEST(ScatfunReader, RejectsAWrongSize) {
  const std::string bytes = small_grey().bytes();
  EXPECT_TRUE(throws_naming(bytes + '\0', "file size"));
  EXPECT_TRUE(throws_naming(bytes.substr(0, bytes.size() - 1), "file size"));
  EXPECT_TRUE(throws_naming(bytes.substr(0, 63), "file size"));
}

TEST(ScatfunReader, RejectsHeaderViolations) {
  {
    std::string bytes = small_grey().bytes();
    bytes[3] = 'X';
    EXPECT_TRUE(throws_naming(bytes, "magic"));
  }
  {
    Builder b = small_grey();
    b.version = 2;
    EXPECT_TRUE(throws_naming(b.bytes(), "version byte must be exactly 1"));
  }
  {
    Builder b = small_grey();
    b.flags = 3;
    EXPECT_TRUE(throws_naming(b.bytes(), "flags must be exactly 1"));
  }
  {
    Builder b = small_grey();
    b.n_channels = 2;
    EXPECT_TRUE(throws_naming(b.bytes(), "nChannels must be 1 or 3"));
  }
  {
    Builder b = small_grey();
    b.n_bases = 2;
    EXPECT_TRUE(throws_naming(b.bytes(), "nBases must be 1"));
  }
  {
    Builder b = small_grey();
    b.n_parameters = 1;
    EXPECT_TRUE(throws_naming(b.bytes(), "nParameters must be 0"));
  }
  {
    Builder b = small_grey();
    b.n_parameter_values = 1;
    EXPECT_TRUE(throws_naming(b.bytes(), "nParameterValues must be 0"));
  }
}

TEST(ScatfunReader, RejectsBadNodes) {
  {
    Builder b = small_grey();
    b.mu[0] = -0.99f;
    EXPECT_TRUE(throws_naming(b.bytes(), "mu must start at exactly -1 and end at exactly +1"));
  }
  {
    Builder b = small_grey();
    b.mu[5] = 0.99f;
    EXPECT_TRUE(throws_naming(b.bytes(), "mu must start at exactly -1 and end at exactly +1"));
  }
  {
    Builder b = small_grey();
    b.mu[4] = -0.25f;  // decreasing after the zeros
    EXPECT_TRUE(throws_naming(b.bytes(), "mu must be ascending"));
  }
  {
    Builder b = small_grey();
    b.mu[2] = -0.5f;  // a doubled value away from 0
    EXPECT_TRUE(throws_naming(b.bytes(), "mu must be ascending"));
  }
  {
    Builder b({-1.0f, 0.0f, 0.0f, 0.0f, 0.5f, 1.0f});  // 0 tripled
    EXPECT_TRUE(throws_naming(b.bytes(), "mu must be ascending"));
  }
}

TEST(ScatfunReader, RejectsBadEntries) {
  {
    Builder b = small_grey();
    b.set(2, 4, {{0.1f}});  // row on the first zero node
    EXPECT_TRUE(throws_naming(b.bytes(), "zero node must have length 0"));
  }
  {
    Builder b = small_grey();
    b.set(4, 3, {{0.1f}});  // column on the second zero node
    EXPECT_TRUE(throws_naming(b.bytes(), "zero node must have length 0"));
  }
  {
    Builder b = small_grey();
    b.offset[4 * 6 + 1] = static_cast<std::uint32_t>(b.coeffs.size()) - 1;  // length 2 from the last float
    EXPECT_TRUE(throws_naming(b.bytes(), "exceeds nCoeffs"));
  }
  {
    Builder b(kSixNodes, 3);  // fits one block, not three
    b.set(4, 1, {{0.3f, 0.1f}, {0.2f, 0.1f}, {0.1f, 0.0f}});
    b.offset[4 * 6 + 1] = 2;
    EXPECT_TRUE(throws_naming(b.bytes(), "offset + nChannels * length = 8 exceeds nCoeffs = 6"));
  }
  {
    Builder b = small_grey();
    b.m_max = 2;
    EXPECT_TRUE(throws_naming(b.bytes(), "exceeds mMax"));
  }
  {
    Builder b = small_grey();
    b.set(4, 0, {{-0.01f, 0.1f}});
    b.cdf.assign(36, 0.0f);
    EXPECT_TRUE(throws_naming(b.bytes(), "a0 must be >= 0"));
  }
}

TEST(ScatfunReader, RejectsBadCdf) {
  {
    Builder b = small_grey();
    b.cdf = b.default_cdf();
    b.cdf[4 * 6 + 3] = b.cdf[4 * 6 + 2] - 0.01f;
    EXPECT_TRUE(throws_naming(b.bytes(), "cdf row 4 must be non-decreasing"));
  }
  {
    Builder b = small_grey();
    b.cdf = b.default_cdf();
    b.cdf[2 * 6] = 0.01f;
    EXPECT_TRUE(throws_naming(b.bytes(), "cdf row 2 must start at 0"));
  }
}

// Hand-integrated Catmull-Rom CDFs on the six-node grid (sheet §1, "CDF"): row 1 holds a0 = 0.3 at column 1 only;
// row 4 holds a0 = 0.1, 0.3, 0, 0, 0.2, 0.4. Segments of width 0.5 give, e.g. for row 1's first,
// 0.5 * ((0 + 0.3) / 2 + (0.3 - 0) / 12) = 0.0875 (d0 one-sided = 0.3, d1 = 0.5 * (0 - 0) / 1 = 0).
TEST(ScatfunReader, CdfErrorAgainstHandIntegratedRows) {
  Builder b(kSixNodes);
  b.set(1, 1, {{0.3f}});
  b.set(4, 0, {{0.1f}});
  b.set(4, 1, {{0.3f}});
  b.set(4, 4, {{0.2f}});
  b.set(4, 5, {{0.4f}});
  b.cdf.assign(36, 0.0f);
  const std::vector<double> row1 = {0.0, 0.0875, 0.175, 0.175, 0.175, 0.175};
  const std::vector<double> row4 = {0.0, 0.265 / 2.4, 0.47 / 2.4, 0.47 / 2.4, 0.59 / 2.4, 0.95 / 2.4};
  for (std::size_t k = 0; k < 6; ++k) {
    b.cdf[1 * 6 + k] = static_cast<float>(row1[k]);
    b.cdf[4 * 6 + k] = static_cast<float>(row4[k]);
  }
  EXPECT_LT(scatfun_cdf_error(parse_scatfun(b.bytes())), 1e-6);

  Builder off = b;
  off.cdf[4 * 6 + 4] = 0.25f;  // relative to row 4's final 0.95 / 2.4
  EXPECT_NEAR(scatfun_cdf_error(parse_scatfun(off.bytes())), (0.25 - 0.59 / 2.4) / (0.95 / 2.4), 1e-6);

  Builder empty_row = b;
  empty_row.cdf[5 * 6 + 5] = 0.01f;  // row 5 has no entries: its error is absolute
  EXPECT_NEAR(scatfun_cdf_error(parse_scatfun(empty_row.bytes())), 0.01, 1e-6);
}

// --- evaluation ---

// At a node pair only that entry contributes: its Fourier sum over |muI|. Row = the muO node, column = the muI node.
TEST(ScatfunReader, NodePairGivesTheEntrysFourierSumOverMuI) {
  const ScatfunFile file = parse_scatfun(small_grey().bytes());
  expect_grey(eval(file, -0.5, 0.5, 0.5), (0.3 + 0.1 * 0.5) / 0.5);
  expect_grey(eval(file, -0.5, 0.5, -1.0), (0.3 - 0.1) / 0.5);
  expect_grey(eval(file, -0.5, 0.5, 0.0), 0.3 / 0.5);
  // The transposed slot: muO = -0.5, muI = +0.5 reads entry (row 1, col 4); three terms, cos 2phi = 2 cos^2 phi - 1.
  expect_grey(eval(file, 0.5, -0.5, 0.5), (0.15 + 0.05 * 0.5 + 0.02 * (2 * 0.25 - 1)) / 0.5);
  // muO = +1 is the last node (t = 1 in the last interval); wo along the normal has no azimuth: cosPhi = 1.
  expect_grey(pbrt_fourier_f(file, {0.0, 0.0, 1.0}, {std::sqrt(0.75), 0.0, 0.5}, true), (0.25 + 0.1 + 0.05) / 0.5);
  expect_grey(eval(file, -0.5, 1.0, -0.5), (0.25 + 0.1 + 0.05) / 0.5);
  // Light at grazing (muI = 0) scales by 0; outside [mu[0], mu[last]] there is no value.
  expect_grey(pbrt_fourier_f(file, {0.0, std::sqrt(0.75), 0.5}, {1.0, 0.0, 0.0}, true), 0.0);
  expect_grey(pbrt_fourier_f(file, {0.0, 0.0, 1.0 + 1e-9}, {std::sqrt(0.75), 0.0, 0.5}, true), 0.0);
}

// Radiance mode multiplies transmission (muI * muO > 0) by (1/eta)^2 for muI > 0 and by eta^2 for muI < 0;
// reflection and importance mode are left alone.
TEST(ScatfunReader, EtaSquaredOnlyForTransmissionInRadianceMode) {
  Builder b(kSixNodes);
  b.eta = 1.5f;
  b.set(4, 4, {{0.2f}});  // muO 0.5, muI 0.5
  b.set(1, 1, {{0.2f}});  // muO -0.5, muI -0.5
  b.set(4, 1, {{0.2f}});  // reflection
  const ScatfunFile file = parse_scatfun(b.bytes());
  const double plain = 0.2 / 0.5;
  expect_grey(eval(file, 0.5, 0.5, 1.0), plain / 2.25);
  expect_grey(eval(file, -0.5, -0.5, 1.0), plain * 2.25);
  expect_grey(eval(file, -0.5, 0.5, 1.0), plain);
  expect_grey(eval(file, 0.5, 0.5, 1.0, false), plain);
  expect_grey(eval(file, -0.5, -0.5, 1.0, false), plain);
  expect_grey(eval(file, -0.5, 0.5, 1.0, false), plain);
}

// Channels Y, R, B; G = 1.39829 Y - 0.100913 B - 0.297375 R; each of R, G, B clamped at 0 (G from the unclamped R).
TEST(ScatfunReader, RgbFileRebuildsGreen) {
  Builder b(kSixNodes, 3);
  b.set(4, 1, {{0.3f, 0.1f}, {0.4f, 0.05f}, {0.2f, -0.02f}});
  b.set(5, 1, {{0.2f}, {-0.1f}, {0.1f}});
  const ScatfunFile file = parse_scatfun(b.bytes());

  const double y = 0.3 + 0.1 * 0.5, r = 0.4 + 0.05 * 0.5, bl = 0.2 - 0.02 * 0.5;
  const auto rgb = eval(file, -0.5, 0.5, 0.5);
  EXPECT_NEAR(rgb[0], r / 0.5, kTol);
  EXPECT_NEAR(rgb[1], (1.39829 * y - 0.100913 * bl - 0.297375 * r) / 0.5, kTol);
  EXPECT_NEAR(rgb[2], bl / 0.5, kTol);

  const auto clamped = eval(file, -0.5, 1.0, 0.5);
  EXPECT_EQ(clamped[0], 0.0);
  EXPECT_NEAR(clamped[1], (1.39829 * 0.2 - 0.100913 * 0.1 + 0.297375 * 0.1) / 0.5, kTol);
  EXPECT_NEAR(clamped[2], 0.1 / 0.5, kTol);
}

// A non-uniform ten-node grid of exact binary fractions, zero nodes at indices 4 and 5.
const std::vector<float> kTenNodes = {-1.0f, -0.75f, -0.5f, -0.125f, 0.0f, 0.0f, 0.125f, 0.5f, 0.75f, 1.0f};

// Catmull-Rom weights by hand: muI = -0.625 lies in [-0.75, -0.5] (idx 1, t = 1/2):
//   w = [-(1/8)(1/4)/(1/2), 1/2 + (1/8)(1/4)/(5/8), 1/2 + (1/8)(1/4)/(1/2), -(1/8)(1/4)/(5/8)]
//     = [-0.0625, 0.55, 0.5625, -0.05] on nodes 0..3;
// muO = 0.625 mirrors it: [-0.05, 0.5625, 0.55, -0.0625] on nodes 6..9. The blended series is as long as the longest.
TEST(ScatfunReader, BetweenNodesIsTheHandComputedBlend) {
  Builder b(kTenNodes);
  b.set(7, 1, {{0.2f}});
  b.set(8, 2, {{0.4f, 0.1f}});
  const ScatfunFile file = parse_scatfun(b.bytes());
  const double w = 0.5625 * 0.55;  // both entries: wO[1] wI[1] and wO[2] wI[2]
  expect_grey(eval(file, -0.625, 0.625, 0.5), (w * 0.2 + w * (0.4 + 0.1 * 0.5)) / 0.625);
  expect_grey(eval(file, -0.625, 0.5, 0.0), 0.55 * 0.2 / 0.625);  // muO on node 7: only row 7

  Builder negative(kTenNodes);  // the only entry sits under a negative weight: Y clamps at 0
  negative.set(7, 3, {{1.0f}});
  expect_grey(eval(parse_scatfun(negative.bytes()), -0.625, 0.5, 1.0), 0.0);
}

// Data linear in the column mu and in the row mu is reproduced exactly between nodes wherever the 4 x 4
// neighbourhood avoids the zero nodes, at interior intervals (central differences) and end intervals (one-sided).
TEST(ScatfunReader, BetweenNodesLinearDataIsReproduced) {
  Builder b(kTenNodes);
  auto a0 = [](double mu_i, double mu_o) { return 0.5 + 0.2 * mu_i + 0.1 * mu_o; };
  auto a1 = [](double mu_i) { return 0.05 + 0.03 * mu_i; };
  for (std::size_t row = 6; row < 10; ++row) {
    for (std::size_t col = 0; col < 4; ++col) {
      b.set(row, col,
            {{static_cast<float>(a0(kTenNodes[col], kTenNodes[row])), static_cast<float>(a1(kTenNodes[col]))}});
    }
  }
  const ScatfunFile file = parse_scatfun(b.bytes());
  for (const auto& [mu_i, mu_o] : {std::pair{-0.625, 0.625}, std::pair{-0.9, 0.9}, std::pair{-0.7, 0.7},
                                   std::pair{-0.6, 0.95}, std::pair{-0.55, 0.6}}) {
    SCOPED_TRACE("muI " + std::to_string(mu_i) + ", muO " + std::to_string(mu_o));
    expect_grey(eval(file, mu_i, mu_o, 0.5), (a0(mu_i, mu_o) + 0.5 * a1(mu_i)) / -mu_i);
  }
}

}  // namespace
}  // namespace skinlayer::test
