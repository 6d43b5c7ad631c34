// skinlayer figures -o DIR, run once for the whole suite: every figure's PNG and CSV exist and are non-empty, each
// PNG decodes at the size index.html states, index.html shows every PNG, and sampled rows of every CSV equal
// skinlayer eval at those points with the material flags the CSV records.
#include <gtest/gtest.h>
#include <stb_image.h>  // libstb.so holds the implementation
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kFigureCount = 16;
constexpr std::size_t kSkinFigureCount = 4;  // the spectral skin's: checked against spectrum and albedo
constexpr std::size_t kRowsPerFile = 20;
constexpr double kRelativeTolerance = 1e-9;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream stream(line);
  while (std::getline(stream, field, separator)) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.emplace_back();
  return fields;
}

struct Csv {
  std::map<std::string, std::size_t> column;  // header name -> index
  std::vector<std::vector<std::string>> rows;
};

Csv read_csv(const fs::path& path) {
  Csv csv;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line, ',');
  for (std::size_t k = 0; k < header.size(); ++k) csv.column[header[k]] = k;
  while (std::getline(in, line)) csv.rows.push_back(split(line, ','));
  return csv;
}

struct StatedPng {
  std::string name;  // file stem
  int width = 0;
  int height = 0;
};

// `skinlayer figures` as the ctest fixture figures.generate ran it (tests/app/figures/CMakeLists.txt): its folder,
// and its output, error stream and exit code beside it.
class FiguresCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = SKINLAYER_FIGURES_DIR;
    const std::string code = read_text(fs::path(dir_.string() + ".code"));
    result_.exit_code = code.empty() ? -1 : std::stoi(code);
    result_.out = read_text(fs::path(dir_.string() + ".out"));
    result_.err = read_text(fs::path(dir_.string() + ".err"));
    const std::string index = read_text(dir_ / "index.html");
    const std::regex img(R"re(<img src="([^"]+)\.png" width="(\d+)" height="(\d+)")re");
    for (auto it = std::sregex_iterator(index.begin(), index.end(), img); it != std::sregex_iterator(); ++it) {
      stated_.push_back({(*it)[1].str(), std::stoi((*it)[2].str()), std::stoi((*it)[3].str())});
    }
  }

  static inline fs::path dir_;
  static inline ProcessResult result_;
  static inline std::vector<StatedPng> stated_;
};

TEST_F(FiguresCommand, SucceedsWithOneProgressLinePerFigure) {
  ASSERT_EQ(result_.exit_code, 0) << result_.err;
  EXPECT_TRUE(result_.err.empty()) << result_.err;
  for (std::size_t k = 1; k <= kFigureCount; ++k) {
    std::ostringstream prefix_text;  // "[k/n] "
    prefix_text << '[' << k << '/' << kFigureCount << "] ";
    const std::string prefix = prefix_text.str();
    EXPECT_NE(result_.out.find(prefix), std::string::npos) << "no progress line " << prefix << "in\n" << result_.out;
  }
  EXPECT_EQ(stated_.size(), kFigureCount);
}

TEST_F(FiguresCommand, EveryFigureHasANonEmptyPngAndCsv) {
  ASSERT_EQ(stated_.size(), kFigureCount);
  for (const StatedPng& figure : stated_) {
    for (const char* extension : {".png", ".csv"}) {
      const fs::path path = dir_ / (figure.name + extension);
      ASSERT_TRUE(fs::exists(path)) << path;
      EXPECT_GT(fs::file_size(path), 0u) << path;
    }
  }
}

TEST_F(FiguresCommand, EveryPngDecodesAtItsStatedSize) {
  ASSERT_EQ(stated_.size(), kFigureCount);
  for (const StatedPng& figure : stated_) {
    const fs::path path = dir_ / (figure.name + ".png");
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr) << path;
    // Not blank: some pixels differ from the first.
    bool varied = false;
    for (int k = 1; k < width * height && !varied; ++k) varied = !std::equal(pixels, pixels + 4, pixels + 4 * k);
    stbi_image_free(pixels);
    EXPECT_EQ(width, figure.width) << path;
    EXPECT_EQ(height, figure.height) << path;
    EXPECT_TRUE(varied) << path << " is blank";
  }
}

// Every figure remembers its (first curve's) material: `material --material FIG.png` reads it back.
TEST_F(FiguresCommand, EveryPngCarriesItsMaterial) {
  ASSERT_EQ(stated_.size(), kFigureCount);
  for (const StatedPng& figure : stated_) {
    const ProcessResult material = run_skinlayer({"material", "--material", (dir_ / (figure.name + ".png")).string()});
    ASSERT_EQ(material.exit_code, 0) << figure.name << ": " << material.err;
    EXPECT_NE(material.out.find("\"name\": \"" + figure.name + "\""), std::string::npos) << material.out;
  }
}

TEST_F(FiguresCommand, IndexShowsEveryPngAndLinksEveryCsv) {
  const std::string index = read_text(dir_ / "index.html");
  std::size_t pngs = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir_)) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() == ".png") {
      ++pngs;
      EXPECT_NE(index.find("src=\"" + file + "\""), std::string::npos) << file;
    } else if (entry.path().extension() == ".csv") {
      EXPECT_NE(index.find("href=\"" + file + "\""), std::string::npos) << file;
    }
  }
  EXPECT_EQ(pngs, kFigureCount);
}

// Every CSV: ~20 rows spread over the file (both sides, every curve), grouped by material, each group evaluated by
// one skinlayer eval run with the recorded flags; f must equal eval's column named by `quantity`.
TEST_F(FiguresCommand, CsvValuesEqualEvalAtThosePoints) {
  ASSERT_EQ(stated_.size(), kFigureCount);
  std::size_t compared = 0;
  for (const StatedPng& figure : stated_) {
    const Csv csv = read_csv(dir_ / (figure.name + ".csv"));
    if (csv.column.contains("skin")) continue;  // SkinCsvValuesEqualSpectrumAndAlbedo
    for (const char* name : {"curve", "parameter", "value", "theta_i", "theta_o", "phi", "side", "quantity", "f",
                             "model", "sigma", "eta", "T", "albedo", "g", "layers"}) {
      ASSERT_TRUE(csv.column.contains(name)) << figure.name << ".csv has no column " << name;
    }
    ASSERT_FALSE(csv.rows.empty()) << figure.name;
    const auto field = [&](const std::vector<std::string>& row, const char* name) {
      return row.at(csv.column.at(name));
    };
    // The eval flags of a row, and the rows to check per flag set.
    std::map<std::vector<std::string>, std::vector<const std::vector<std::string>*>> groups;
    const std::size_t stride = std::max<std::size_t>(1, csv.rows.size() / kRowsPerFile);
    for (std::size_t k = stride / 2; k < csv.rows.size(); k += stride) {
      const std::vector<std::string>& row = csv.rows[k];
      ASSERT_EQ(row.size(), csv.column.size()) << figure.name << " row " << k;
      if (field(row, "quantity") == "interface_btdf") continue;  // core's microfacet_btdf: no eval column
      std::vector<std::string> flags = {"eval",
                                        "--model",
                                        field(row, "model"),
                                        "--sigma",
                                        field(row, "sigma"),
                                        "--eta",
                                        field(row, "eta"),
                                        "--microfacet",
                                        field(row, "microfacet")};
      const std::string layers = field(row, "layers");
      if (layers.empty()) {
        flags.insert(flags.end(), {"--T", field(row, "T"), "--albedo", field(row, "albedo"), "--g", field(row, "g")});
      } else {  // a stack: its --layer values, ' '-separated, ';' for ','
        for (std::string spec : split(layers, ' ')) {
          std::replace(spec.begin(), spec.end(), ';', ',');
          flags.insert(flags.end(), {"--layer", spec});
        }
      }
      groups[flags].push_back(&row);
    }
    ASSERT_FALSE(groups.empty()) << figure.name;
    for (const auto& [flags, rows] : groups) {
      std::string input = "theta_i,theta_o,phi\n";
      for (const auto* row : rows) {
        input += field(*row, "theta_i") + "," + field(*row, "theta_o") + "," + field(*row, "phi") + "\n";
      }
      const ProcessResult eval = run_skinlayer(flags, input);
      ASSERT_EQ(eval.exit_code, 0) << eval.err;
      std::istringstream lines(eval.out);
      std::string line;
      std::getline(lines, line);
      const std::vector<std::string> header = split(line, ',');
      for (const auto* row : rows) {
        ASSERT_TRUE(std::getline(lines, line));
        const std::vector<std::string> values = split(line, ',');
        const auto column = std::find(header.begin(), header.end(), field(*row, "quantity"));
        ASSERT_NE(column, header.end()) << field(*row, "quantity");
        const double expected = std::stod(values.at(static_cast<std::size_t>(column - header.begin())));
        const double actual = std::stod(field(*row, "f"));
        EXPECT_LE(std::abs(actual - expected), kRelativeTolerance * std::max(std::abs(expected), std::abs(actual)))
            << figure.name << ": " << field(*row, "curve") << " side " << field(*row, "side") << " at "
            << field(*row, "theta_i") << "," << field(*row, "theta_o") << "," << field(*row, "phi");
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, (kFigureCount - kSkinFigureCount) * kRowsPerFile * 3 / 4);
}

// The spectral skin's CSVs: every reflectance on the 10 nm grid equals `skinlayer spectrum --skin ... --theta-i ...`
// at its wavelength (the spectra), or `skinlayer albedo --skin ... --theta-i 0`'s RGB reflectance (the spheres), with
// the recorded skin and top interface.
TEST_F(FiguresCommand, SkinCsvValuesEqualSpectrumAndAlbedo) {
  std::size_t skin_figures = 0, compared = 0;
  for (const StatedPng& figure : stated_) {
    const Csv csv = read_csv(dir_ / (figure.name + ".csv"));
    if (!csv.column.contains("skin") || csv.column.contains("r_inner_mm")) continue;  // profiles: below
    ++skin_figures;
    const auto field = [&](const std::vector<std::string>& row, const char* name) {
      return row.at(csv.column.at(name));
    };
    const bool spectra = csv.column.contains("wavelength_nm");
    std::map<std::vector<std::string>, std::vector<const std::vector<std::string>*>> groups;  // one run per skin
    for (const std::vector<std::string>& row : csv.rows) {
      std::string skin = field(row, "skin");
      std::replace(skin.begin(), skin.end(), ';', ',');
      groups[{spectra ? "spectrum" : "albedo", "--skin", skin, "--sigma", field(row, "sigma"), "--eta",
              field(row, "eta"), "--theta-i", field(row, "theta_i")}]
          .push_back(&row);
    }
    for (const auto& [flags, rows] : groups) {
      const ProcessResult run = run_skinlayer(flags);
      ASSERT_EQ(run.exit_code, 0) << run.err;
      std::istringstream lines(run.out);
      std::string line;
      std::getline(lines, line);
      const std::vector<std::string> header = split(line, ',');
      const auto at = [&](const std::vector<std::string>& values, const std::string& name) {
        const auto column = std::find(header.begin(), header.end(), name);
        EXPECT_NE(column, header.end()) << name;
        return std::stod(values.at(static_cast<std::size_t>(column - header.begin())));
      };
      std::map<std::string, std::vector<std::string>> by_wavelength;  // spectrum's rows by wavelength
      std::vector<std::string> albedo_row;
      while (std::getline(lines, line)) {
        const std::vector<std::string> values = split(line, ',');
        if (spectra) {
          by_wavelength[values.at(1)] = values;
        } else {
          albedo_row = values;
        }
      }
      for (const auto* row : rows) {
        if (spectra) {  // the figure's 5 nm grid: every other row is on spectrum's 10 nm grid
          if (!by_wavelength.contains(field(*row, "wavelength_nm"))) continue;
          const double expected = at(by_wavelength.at(field(*row, "wavelength_nm")), "reflectance");
          EXPECT_NEAR(std::stod(field(*row, "reflectance")), expected, kRelativeTolerance * expected)
              << figure.name << " " << field(*row, "curve") << " at " << field(*row, "wavelength_nm");
        } else {
          for (const char* channel : {"reflectance_r", "reflectance_g", "reflectance_b"}) {
            const double expected = at(albedo_row, channel);
            EXPECT_NEAR(std::stod(field(*row, channel)), expected, kRelativeTolerance * expected)
                << figure.name << " " << field(*row, "curve") << " " << channel;
          }
        }
        ++compared;
      }
    }
  }
  EXPECT_EQ(skin_figures, kSkinFigureCount);
  EXPECT_GE(compared, 2u * 5u * 31u + 5u);
}

// The skin profiles' CSV: the first skin's rows at each wavelength equal `skinlayer profile --skin ... --wavelength W
// --annuli 0.2:20` (the other skins' are made the same way).
TEST_F(FiguresCommand, SkinProfileCsvEqualsTheProfileCommand) {
  const Csv csv = read_csv(dir_ / "skin-profiles.csv");
  ASSERT_FALSE(csv.rows.empty());
  const auto field = [&](const std::vector<std::string>& row, const char* name) { return row.at(csv.column.at(name)); };
  const std::string first = field(csv.rows.front(), "curve");
  std::map<std::string, std::vector<const std::vector<std::string>*>> by_wavelength;
  for (const std::vector<std::string>& row : csv.rows) {
    if (field(row, "curve") == first) by_wavelength[field(row, "wavelength_nm")].push_back(&row);
  }
  ASSERT_EQ(by_wavelength.size(), 3u);
  for (const auto& [wavelength, rows] : by_wavelength) {
    std::string skin = field(*rows.front(), "skin");
    std::replace(skin.begin(), skin.end(), ';', ',');
    const ProcessResult run =
        run_skinlayer({"profile", "--skin", skin, "--sigma", field(*rows.front(), "sigma"), "--eta",
                       field(*rows.front(), "eta"), "--wavelength", wavelength, "--annuli", "0.2:20"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::istringstream lines(run.out);
    std::string line;
    std::getline(lines, line);
    std::size_t i = 0;
    while (std::getline(lines, line) && i < rows.size()) {
      const std::vector<std::string> values = split(line, ',');
      EXPECT_EQ(values.at(0), field(*rows[i], "r_inner_mm"));
      const double expected = std::stod(values.at(2));
      EXPECT_NEAR(std::stod(field(*rows[i], "reflectance")), expected, kRelativeTolerance * expected)
          << wavelength << " nm, annulus " << i;
      ++i;
    }
    EXPECT_EQ(i, rows.size());
  }
}

// The rescaled figure: plotted is f over the curve's peak, so each curve's largest plotted value is 1.
TEST_F(FiguresCommand, RescaledCurvesPeakAtOne) {
  std::size_t rescaled_files = 0;
  for (const StatedPng& figure : stated_) {
    const Csv csv = read_csv(dir_ / (figure.name + ".csv"));
    if (!csv.column.contains("plotted")) continue;
    ++rescaled_files;
    std::map<std::string, double> peak, peak_f;
    for (const auto& row : csv.rows) {
      const std::string& curve = row.at(csv.column.at("curve"));
      const double f = std::stod(row.at(csv.column.at("f")));
      const double plotted = std::stod(row.at(csv.column.at("plotted")));
      peak[curve] = std::max(peak[curve], plotted);
      peak_f[curve] = std::max(peak_f[curve], f);
    }
    for (const auto& [curve, value] : peak) {
      EXPECT_NEAR(value, 1.0, 1e-12) << figure.name << ": " << curve;
      EXPECT_GT(peak_f.at(curve), 0.0) << figure.name << ": " << curve;
    }
  }
  EXPECT_EQ(rescaled_files, 1u);
}

// --only draws the named figures alone, and index.html shows those; an unknown name lists the figures and makes no
// folder.
TEST(FiguresCommandOnly, DrawsTheNamedFiguresAlone) {
  const fs::path dir = fs::path(::testing::TempDir()) / "skinlayer_figures_only";
  fs::remove_all(dir);
  const ProcessResult result =
      run_skinlayer({"figures", "-o", dir.string(), "--size", "160", "--only", "surface-eta,subsurface-g"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::vector<std::string> written;
  for (const auto& entry : fs::directory_iterator(dir)) written.push_back(entry.path().filename().string());
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written, (std::vector<std::string>{"index.html", "subsurface-g.csv", "subsurface-g.png", "surface-eta.csv",
                                               "surface-eta.png"}));
  EXPECT_NE(result.out.find("[2/2]"), std::string::npos) << result.out;
  fs::remove_all(dir);
  const fs::path never = fs::path(::testing::TempDir()) / "skinlayer_figures_never";
  const ProcessResult typo = run_skinlayer({"figures", "-o", never.string(), "--only", "surface-etta"});
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.err.find("'surface-etta' is not a figure"), std::string::npos) << typo.err;
  EXPECT_NE(typo.err.find("skin-profiles"), std::string::npos) << typo.err;
  EXPECT_FALSE(fs::exists(never));
}

TEST(FiguresCommandErrors, MissingOutputIsAUsageError) {
  const ProcessResult result = run_skinlayer({"figures"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("-o DIR"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace skinlayer::test
