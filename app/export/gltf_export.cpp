#include "app/export/gltf_export.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "app/export/fit_report_json.h"
#include "app/material/material_json.h"
#include "core/conventions.h"
#include "core/fit/brdf_fit_target.h"

namespace skinlayer {
namespace {

nlohmann::ordered_json channels(const Rgb& values) { return {values(0), values(1), values(2)}; }

// glTF's component types and buffer targets (the specification's accessor.componentType, bufferView.target).
constexpr int kFloat = 5126, kUnsignedShort = 5123;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

template <typename T>
void append(std::vector<unsigned char>& bytes, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));  // little-endian hosts only, as glTF's buffers are
  bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

// A unit sphere: (rings + 1) x (segments + 1) vertices from the north pole down (the seam's column doubled, so that
// a texture could wrap), its normal its position; two triangles per quad, one at each pole (the other would be
// degenerate), counter-clockwise seen from outside.
struct Sphere {
  std::vector<float> positions;  // xyz per vertex
  std::vector<std::uint16_t> indices;
};

Sphere uv_sphere(int rings, int segments) {
  if (rings < 2 || segments < 3 || (rings + 1) * (segments + 1) > 65535) {
    throw std::invalid_argument(
        "gltf export: the sphere needs rings >= 2, segments >= 3 and fewer than 65536 vertices");
  }
  Sphere sphere;
  for (int r = 0; r <= rings; ++r) {
    const double theta = kPi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const double phi = 2.0 * kPi * s / segments;
      // y up (glTF's), the sphere's +z toward a default camera.
      sphere.positions.push_back(static_cast<float>(std::sin(theta) * std::sin(phi)));
      sphere.positions.push_back(static_cast<float>(std::cos(theta)));
      sphere.positions.push_back(static_cast<float>(std::sin(theta) * std::cos(phi)));
    }
  }
  const auto vertex = [segments](int r, int s) { return static_cast<std::uint16_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::uint16_t a = vertex(r, s), b = vertex(r + 1, s), c = vertex(r + 1, s + 1), d = vertex(r, s + 1);
      if (r != 0) sphere.indices.insert(sphere.indices.end(), {a, b, d});
      if (r != rings - 1) sphere.indices.insert(sphere.indices.end(), {d, b, c});
    }
  }
  return sphere;
}

bool is_default(const Rgb& value, double fallback) { return (value == fallback).all(); }

}  // namespace

std::string base64_encode(const std::vector<unsigned char>& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::size_t left = bytes.size() - k;
    const std::uint32_t group = (std::uint32_t{bytes[k]} << 16) | (left > 1 ? std::uint32_t{bytes[k + 1]} << 8 : 0u) |
                                (left > 2 ? std::uint32_t{bytes[k + 2]} : 0u);
    text += kAlphabet[(group >> 18) & 63];
    text += kAlphabet[(group >> 12) & 63];
    text += left > 1 ? kAlphabet[(group >> 6) & 63] : '=';
    text += left > 2 ? kAlphabet[group & 63] : '=';
  }
  return text;
}

std::vector<std::string> gltf_extensions_used(const GltfPbrParameters& p) {
  std::vector<std::string> used;
  if (p.ior != 1.5) used.emplace_back("KHR_materials_ior");
  if (p.specular != 1.0 || !is_default(p.specular_color, 1.0)) used.emplace_back("KHR_materials_specular");
  if (p.sheen_color.maxCoeff() > 0.0) used.emplace_back("KHR_materials_sheen");
  if (p.clearcoat > 0.0) used.emplace_back("KHR_materials_clearcoat");
  return used;
}

nlohmann::ordered_json gltf_material(const GltfPbrParameters& p, const std::string& name,
                                     const nlohmann::ordered_json& extras) {
  nlohmann::ordered_json material;
  if (!name.empty()) material["name"] = name;
  material["pbrMetallicRoughness"] = {{"baseColorFactor", {p.base_color(0), p.base_color(1), p.base_color(2), 1.0}},
                                      {"metallicFactor", p.metallic},
                                      {"roughnessFactor", p.roughness}};
  nlohmann::ordered_json extensions = nlohmann::ordered_json::object();
  for (const std::string& extension : gltf_extensions_used(p)) {
    if (extension == "KHR_materials_ior") extensions[extension] = {{"ior", p.ior}};
    if (extension == "KHR_materials_specular") {
      extensions[extension] = {{"specularFactor", p.specular}, {"specularColorFactor", channels(p.specular_color)}};
    }
    if (extension == "KHR_materials_sheen") {
      extensions[extension] = {{"sheenColorFactor", channels(p.sheen_color)},
                               {"sheenRoughnessFactor", p.sheen_roughness}};
    }
    if (extension == "KHR_materials_clearcoat") {
      extensions[extension] = {{"clearcoatFactor", p.clearcoat}, {"clearcoatRoughnessFactor", p.clearcoat_roughness}};
    }
  }
  if (!extensions.empty()) material["extensions"] = extensions;
  if (!extras.is_null()) material["extras"] = extras;
  return material;
}

nlohmann::ordered_json gltf_asset(const GltfPbrParameters& parameters, const std::string& name,
                                  const nlohmann::ordered_json& extras, int rings, int segments) {
  static_cast<void>(GltfPbr(parameters));  // the factors' ranges, checked as the model checks them
  const Sphere sphere = uv_sphere(rings, segments);
  const std::size_t vertices = sphere.positions.size() / 3;
  std::vector<unsigned char> bytes;
  for (const float value : sphere.positions) append(bytes, value);  // positions
  for (const float value : sphere.positions) append(bytes, value);  // normals: the same on a unit sphere
  const std::size_t vector_bytes = vertices * 3 * sizeof(float);
  for (const std::uint16_t index : sphere.indices) append(bytes, index);
  const std::size_t index_bytes = sphere.indices.size() * sizeof(std::uint16_t);
  while (bytes.size() % 4 != 0) bytes.push_back(0);  // a buffer's length padded to 4 bytes

  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (std::size_t v = 0; v < vertices; ++v) {
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], sphere.positions[3 * v + c]);
      hi[c] = std::max(hi[c], sphere.positions[3 * v + c]);
    }
  }

  nlohmann::ordered_json asset;
  asset["asset"] = {{"version", "2.0"}, {"generator", "skinlayer"}};
  const std::vector<std::string> used = gltf_extensions_used(parameters);
  if (!used.empty()) asset["extensionsUsed"] = used;
  asset["scene"] = 0;
  asset["scenes"] = {{{"nodes", {0}}}};
  asset["nodes"] = {{{"mesh", 0}, {"name", "sphere"}}};
  asset["meshes"] = {
      {{"name", "sphere"},
       {"primitives",
        {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}, {"material", 0}, {"mode", 4}}}}}};
  asset["materials"] = {gltf_material(parameters, name, extras)};
  asset["accessors"] = {
      {{"bufferView", 0},
       {"componentType", kFloat},
       {"count", vertices},
       {"type", "VEC3"},
       {"min", {lo[0], lo[1], lo[2]}},
       {"max", {hi[0], hi[1], hi[2]}}},
      {{"bufferView", 1}, {"componentType", kFloat}, {"count", vertices}, {"type", "VEC3"}},
      {{"bufferView", 2}, {"componentType", kUnsignedShort}, {"count", sphere.indices.size()}, {"type", "SCALAR"}}};
  asset["bufferViews"] = {
      {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", vector_bytes}, {"target", kArrayBuffer}},
      {{"buffer", 0}, {"byteOffset", vector_bytes}, {"byteLength", vector_bytes}, {"target", kArrayBuffer}},
      {{"buffer", 0}, {"byteOffset", 2 * vector_bytes}, {"byteLength", index_bytes}, {"target", kElementArrayBuffer}}};
  asset["buffers"] = {
      {{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64_encode(bytes)}}};
  return asset;
}

std::string gltf_export(const MaterialDocument& document, const DocumentFit<GltfFit>& fit) {
  const GltfPbr model(fit.fit.parameters);
  nlohmann::ordered_json off_normal;
  for (const int degrees : {30, 60})
    off_normal[std::to_string(degrees)] = channels(model.albedo(std::cos(degrees_to_radians(degrees))));
  const nlohmann::ordered_json extras = {{"skinlayer_fit", gltf_fit_json(fit)},
                                         {"gltf_model_albedo_at_normal_incidence", channels(model.albedo(1.0))},
                                         {"gltf_model_albedo_at_degrees", off_normal},
                                         {"skinlayer_material", material_json(document)}};
  return gltf_asset(fit.fit.parameters, document.name.empty() ? "skinlayer" : document.name, extras).dump(2) + "\n";
}

}  // namespace skinlayer
