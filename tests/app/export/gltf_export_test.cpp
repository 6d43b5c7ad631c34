// The glTF export (app/export/gltf_export.h) read back with a reader written here from the glTF 2.0 specification's
// rules: the asset's structure, the accessors' counts, min and max against the decoded bytes, the buffer's byteLength
// against its base64 data, triangles facing out, and extensionsUsed naming exactly the extensions the material uses.
#include "app/export/gltf_export.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/gltf_fit_document.h"
#include "core/targets/gltf_pbr.h"
#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"
#include "tests/app/scratch_folder.h"

namespace skinlayer {
namespace {

using Json = nlohmann::ordered_json;

std::vector<unsigned char> base64_decode(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes;
  std::uint32_t group = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const std::size_t value = alphabet.find(c);
    if (value == std::string::npos) throw std::runtime_error("not base64");
    group = (group << 6) | static_cast<std::uint32_t>(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<unsigned char>((group >> bits) & 0xff));
    }
  }
  return bytes;
}

std::vector<unsigned char> buffer_bytes(const Json& asset) {
  const std::string uri = asset.at("buffers").at(0).at("uri");
  const std::string prefix = "data:application/octet-stream;base64,";
  EXPECT_EQ(uri.rfind(prefix, 0), 0u);
  return base64_decode(uri.substr(prefix.size()));
}

template <typename T>
T read(const std::vector<unsigned char>& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

GltfPbrParameters every_extension() {
  GltfPbrParameters p;
  p.metallic = 0.0;
  p.base_color = Rgb(0.6, 0.3, 0.2);
  p.roughness = 0.4;
  p.ior = 1.4;
  p.specular = 0.7;
  p.sheen_color = Rgb::Constant(0.2);
  p.sheen_roughness = 0.5;
  p.clearcoat = 1.0;
  p.clearcoat_roughness = 0.1;
  return p;
}

TEST(GltfExport, TheSphereReadsBackAsTheAccessorsSay) {
  const int rings = 8, segments = 12;
  const Json asset = gltf_asset(every_extension(), "test", nullptr, rings, segments);
  EXPECT_EQ(asset.at("asset").at("version"), "2.0");
  EXPECT_EQ(asset.at("asset").at("generator"), "skinlayer");
  EXPECT_EQ(asset.at("scenes").at(asset.at("scene").get<int>()).at("nodes").at(0), 0);
  const Json& primitive = asset.at("meshes").at(0).at("primitives").at(0);
  EXPECT_EQ(primitive.at("material"), 0);
  EXPECT_EQ(primitive.value("mode", 4), 4);  // triangles

  const std::vector<unsigned char> bytes = buffer_bytes(asset);
  const std::size_t length = asset.at("buffers").at(0).at("byteLength");
  EXPECT_EQ(bytes.size(), length);
  const auto view_of = [&](int accessor) {
    return asset.at("bufferViews").at(asset.at("accessors").at(accessor).at("bufferView").get<int>());
  };
  for (const Json& view : asset.at("bufferViews")) {
    EXPECT_LE(view.at("byteOffset").get<std::size_t>() + view.at("byteLength").get<std::size_t>(), length);
    EXPECT_EQ(view.at("byteOffset").get<std::size_t>() % 4, 0u);
  }

  const Json& position = asset.at("accessors").at(primitive.at("attributes").at("POSITION").get<int>());
  const Json& normal = asset.at("accessors").at(primitive.at("attributes").at("NORMAL").get<int>());
  const Json& index = asset.at("accessors").at(primitive.at("indices").get<int>());
  const std::size_t vertices = (rings + 1) * (segments + 1);
  EXPECT_EQ(position.at("count"), vertices);
  EXPECT_EQ(normal.at("count"), vertices);
  EXPECT_EQ(position.at("componentType"), 5126);
  EXPECT_EQ(index.at("componentType"), 5123);
  // Two triangles per quad but one in each polar ring.
  EXPECT_EQ(index.at("count"), static_cast<std::size_t>(3 * (2 * rings - 2) * segments));
  EXPECT_EQ(view_of(0).at("byteLength"), vertices * 12);

  const std::size_t position_at = view_of(0).at("byteOffset"), normal_at = view_of(1).at("byteOffset");
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  std::vector<Vec3> points;
  for (std::size_t v = 0; v < vertices; ++v) {
    Vec3 p, n;
    for (int c = 0; c < 3; ++c) {
      p(c) = read<float>(bytes, position_at + 12 * v + 4 * c);
      n(c) = read<float>(bytes, normal_at + 12 * v + 4 * c);
      lo[c] = std::min(lo[c], p(c));
      hi[c] = std::max(hi[c], p(c));
    }
    EXPECT_NEAR(p.norm(), 1.0, 1e-6);
    EXPECT_NEAR((n - p).norm(), 0.0, 1e-7);
    points.push_back(p);
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(position.at("min").at(c).get<float>(), static_cast<float>(lo[c]));
    EXPECT_EQ(position.at("max").at(c).get<float>(), static_cast<float>(hi[c]));
  }
  EXPECT_NEAR(hi[1], 1.0, 1e-7);  // the poles on y
  EXPECT_NEAR(lo[1], -1.0, 1e-7);

  const std::size_t index_at = view_of(2).at("byteOffset"), count = index.at("count");
  for (std::size_t t = 0; t < count; t += 3) {
    Vec3 corner[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint16_t i = read<std::uint16_t>(bytes, index_at + 2 * (t + k));
      ASSERT_LT(i, vertices);
      corner[k] = points[i];
    }
    const Vec3 normal_of_triangle = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
    EXPECT_GT(normal_of_triangle.norm(), 1e-6) << "degenerate triangle " << t / 3;
    EXPECT_GT(normal_of_triangle.dot(corner[0] + corner[1] + corner[2]), 0.0) << "triangle " << t / 3 << " faces in";
  }
}

TEST(GltfExport, ListsExactlyTheExtensionsItUses) {
  GltfPbrParameters plain;
  plain.metallic = 0.0;
  plain.roughness = 0.5;
  const Json bare = gltf_asset(plain, "plain", nullptr, 4, 6);
  EXPECT_FALSE(bare.contains("extensionsUsed"));
  EXPECT_FALSE(bare.at("materials").at(0).contains("extensions"));

  const Json full = gltf_asset(every_extension(), "full", nullptr, 4, 6);
  const std::set<std::string> used(full.at("extensionsUsed").begin(), full.at("extensionsUsed").end());
  std::set<std::string> in_material;
  for (const auto& [name, value] : full.at("materials").at(0).at("extensions").items()) in_material.insert(name);
  EXPECT_EQ(used, in_material);
  EXPECT_EQ(used, (std::set<std::string>{"KHR_materials_ior", "KHR_materials_specular", "KHR_materials_sheen",
                                         "KHR_materials_clearcoat"}));
  const Json& material = full.at("materials").at(0);
  EXPECT_EQ(material.at("extensions").at("KHR_materials_ior").at("ior"), 1.4);
  EXPECT_EQ(material.at("pbrMetallicRoughness").at("baseColorFactor").at(3), 1.0);
  EXPECT_EQ(material.at("pbrMetallicRoughness").at("roughnessFactor"), 0.4);

  GltfPbrParameters sheen_only = plain;
  sheen_only.sheen_color = Rgb(0.0, 0.1, 0.0);
  EXPECT_EQ(gltf_extensions_used(sheen_only), std::vector<std::string>{"KHR_materials_sheen"});
}

TEST(GltfExport, Base64IsRfc4648) {
  EXPECT_EQ(base64_encode({}), "");
  EXPECT_EQ(base64_encode({'f'}), "Zg==");
  EXPECT_EQ(base64_encode({'f', 'o'}), "Zm8=");
  EXPECT_EQ(base64_encode({'f', 'o', 'o', 'b', 'a', 'r'}), "Zm9vYmFy");
}

// A preset with a clear coat through the document's fit: clearcoat 1 over the base's relative index, the report
// and the material in the extras, and the parameters in the material those of the report.
TEST(GltfExport, CarriesTheFitOfAClearCoatedPreset) {
  const MaterialDocument document = preset_material("clear-coat-red");
  const GltfFitSettings settings = gltf_fit_settings(document);
  EXPECT_TRUE(settings.clearcoat);
  EXPECT_NEAR(settings.ior, 1.2, 1e-12);
  const DocumentFit<GltfFit> fit = fit_gltf(document, parallel_for_threads);
  const Json asset = Json::parse(gltf_export(document, fit));
  const Json& material = asset.at("materials").at(0);
  EXPECT_EQ(material.at("name"), "clear-coat-red");
  const Json& report = material.at("extras").at("skinlayer_fit");
  EXPECT_EQ(report.at("target"), "gltf");
  EXPECT_EQ(material.at("extras").at("skinlayer_material").at("name"), "clear-coat-red");
  EXPECT_EQ(material.at("extensions").at("KHR_materials_clearcoat").at("clearcoatFactor"), 1.0);
  EXPECT_EQ(material.at("extensions").at("KHR_materials_clearcoat").at("clearcoatRoughnessFactor"),
            report.at("parameters").at("clearcoat_roughness"));
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(material.at("pbrMetallicRoughness").at("baseColorFactor").at(c),
              report.at("parameters").at("base_color").at(c));
  }
  EXPECT_TRUE(report.at("albedo_matched_at_normal_incidence").get<bool>());
  const Rgb model = GltfPbr(fit.fit.parameters).albedo(1.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(material.at("extras").at("gltf_model_albedo_at_normal_incidence").at(c).get<double>(), model(c));
  }
  const Rgb at_60 = GltfPbr(fit.fit.parameters).albedo(0.5);
  EXPECT_NEAR(material.at("extras").at("gltf_model_albedo_at_degrees").at("60").at(0).get<double>(), at_60(0), 1e-12);
  std::printf("  clear-coat-red: %s\n", report.at("parameters").dump().c_str());
  std::printf("  errors: %s\n", report.at("errors").dump().c_str());
}

// The material's factors as a reader finds them: pbrMetallicRoughness's, and each extension's where the material has
// it, glTF's defaults where it has not (the extensions' own schemas), by GltfPbrParameters' names as the fit's report
// has them.
Json factors_in(const Json& material) {
  const Json& pbr = material.at("pbrMetallicRoughness");
  const Json none = Json::object();
  const Json& extensions = material.contains("extensions") ? material.at("extensions") : none;
  const auto extension = [&](const char* name) -> const Json& {
    return extensions.contains(name) ? extensions.at(name) : none;
  };
  const Json base = pbr.value("baseColorFactor", Json{1.0, 1.0, 1.0, 1.0});
  return {{"base_color", {base.at(0), base.at(1), base.at(2)}},
          {"metallic", pbr.value("metallicFactor", 1.0)},
          {"roughness", pbr.value("roughnessFactor", 1.0)},
          {"ior", extension("KHR_materials_ior").value("ior", 1.5)},
          {"specular", extension("KHR_materials_specular").value("specularFactor", 1.0)},
          {"specular_color", extension("KHR_materials_specular").value("specularColorFactor", Json{1.0, 1.0, 1.0})},
          {"sheen_color", extension("KHR_materials_sheen").value("sheenColorFactor", Json{0.0, 0.0, 0.0})},
          {"sheen_roughness", extension("KHR_materials_sheen").value("sheenRoughnessFactor", 0.0)},
          {"clearcoat", extension("KHR_materials_clearcoat").value("clearcoatFactor", 0.0)},
          {"clearcoat_roughness", extension("KHR_materials_clearcoat").value("clearcoatRoughnessFactor", 0.0)}};
}

class GltfExportCommand : public test::ScratchFolderTest {};

// `skinlayer export --format gltf` writes the material `skinlayer fit --target gltf` prints: every factor a reader
// takes from the file (defaults included) is the fit's parameter, the report rides in the extras, and the base's
// alpha is 1 (opaque).
TEST_F(GltfExportCommand, TheFileCarriesTheFitsParameters) {
  const std::string file = path("clear-coat-red.gltf");
  const test::ProcessResult exported =
      test::run_skinlayer({"export", "--format", "gltf", "--preset", "clear-coat-red", "-o", file});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("wrote " + file), std::string::npos) << exported.out;
  const test::ProcessResult fitted = test::run_skinlayer({"fit", "--target", "gltf", "--preset", "clear-coat-red"});
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  const Json report = Json::parse(fitted.out);

  std::ifstream in(file);
  ASSERT_TRUE(in);
  const Json asset = Json::parse(in);
  const Json& material = asset.at("materials").at(0);
  EXPECT_EQ(material.at("pbrMetallicRoughness").at("baseColorFactor").at(3), 1.0);
  const Json factors = factors_in(material);
  const Json& parameters = report.at("parameters");
  for (const auto& [name, value] : factors.items()) {
    ASSERT_TRUE(parameters.contains(name)) << name;
    const Json& expected = parameters.at(name);
    if (value.is_array()) {
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(value.at(c).get<double>(), expected.at(c).get<double>(), 1e-12) << name;
    } else {
      EXPECT_NEAR(value.get<double>(), expected.get<double>(), 1e-12) << name;
    }
  }
  EXPECT_EQ(factors.at("clearcoat"), 1.0);
  EXPECT_EQ(material.at("extras").at("skinlayer_fit").at("parameters"), parameters);
  EXPECT_EQ(material.at("extras").at("skinlayer_fit").at("errors"), report.at("errors"));
}

// The flags of other formats are refused with one line naming the flag and the formats it is for, and no file.
TEST_F(GltfExportCommand, FlagsOfOtherFormatsAreOneLine) {
  const std::string file = path("x.gltf");
  EXPECT_TRUE(test::failed_with_one_line(
      test::run_skinlayer({"export", "--format", "gltf", "--scene", "--preset", "jade", "-o", file}), 2,
      {"--scene", "blender", "blender-3.4"}));
  EXPECT_TRUE(test::failed_with_one_line(
      test::run_skinlayer({"export", "--format", "gltf", "--nodes", "9", "--preset", "jade", "-o", file}), 2,
      {"--nodes", "gltf"}));
  EXPECT_TRUE(test::failed_with_one_line(
      test::run_skinlayer({"export", "--format", "gltf", "--model", "hk", "--preset", "jade", "-o", file}), 2,
      {"--model", "gltf"}));
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace skinlayer
