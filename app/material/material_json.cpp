#include "app/material/material_json.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/material/exact_transparency.h"
#include "app/text/quoted.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {
namespace {

using Json = nlohmann::ordered_json;

std::string type_name(const Json& value) {
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_boolean()) return "a boolean";
  if (value.is_array()) return "a list";
  if (value.is_object()) return "an object";
  return "null";
}

std::string joined(std::initializer_list<std::string_view> names) {
  std::string text;
  for (const std::string_view name : names) text.append(text.empty() ? "" : ", ").append(name);
  return text;
}

// Reads one document, naming the file and the key path ("layers[0].g") in every error.
class DocumentReader {
 public:
  explicit DocumentReader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw MaterialFileError(source_ + ": key \"" + path + "\" " + what);
  }

  void only_keys(const Json& object, const std::string& path, std::initializer_list<std::string_view> valid) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(valid.begin(), valid.end(), key) == valid.end()) {
        throw MaterialFileError(source_ + ": unknown key \"" + join(path, key) + "\"; valid keys " +
                                (path.empty() ? "at the top level" : "in \"" + path + "\"") + ": " + joined(valid));
      }
    }
  }

  const Json& required(const Json& object, const std::string& path, std::string_view key, std::string_view what) const {
    const auto found = object.find(key);
    if (found == object.end()) fail(join(path, key), "is missing (" + std::string(what) + ")");
    return *found;
  }

  const Json& object(const Json& value, const std::string& path) const {
    if (!value.is_object()) fail(path, "must be an object, not " + type_name(value));
    return value;
  }

  std::string text(const Json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "must be a string, not " + type_name(value));
    return value.get<std::string>();
  }

  // A number checked against its row of core's parameter table.
  double parameter(const Json& value, const std::string& path, std::string_view flag) const {
    return parameter(value, path, parameter_info(flag));
  }

  double parameter(const Json& value, const std::string& path, const ParameterInfo& info) const {
    if (!value.is_number()) {
      fail(path, "must be a number in " + range_text(info) + " (" + std::string(info.description) + "), not " +
                     type_name(value));
    }
    const double number = value.get<double>();
    try {
      check_parameter(info, number);
    } catch (const ParameterError& error) {
      fail(path, "is out of range: " + std::string(error.what()));
    }
    return number;
  }

  double required_parameter(const Json& object, const std::string& path, std::string_view key,
                            std::string_view flag) const {
    const ParameterInfo& info = parameter_info(flag);
    return parameter(required(object, path, key, std::string(info.description) + ", a number in " + range_text(info)),
                     join(path, key), flag);
  }

  static std::string join(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
  }

 private:
  std::string source_;
};

Json albedo_json(const AlbedoRgb& rgb) {
  if (rgb[0] == rgb[1] && rgb[1] == rgb[2]) return rgb[0];
  return Json::array({rgb[0], rgb[1], rgb[2]});
}

// Layer `index` (0-based, top to bottom) of the "layers" list: the first one's values go to document.layer, every
// other one is appended to document.layer.below.
void read_layer(const DocumentReader& reader, const Json& layer, std::size_t index, MaterialDocument& document) {
  const std::string path = "layers[" + std::to_string(index) + "]";
  reader.object(layer, path);
  if (index == 0) {
    reader.only_keys(layer, path, {"T", "tau", "albedo", "g", "mu_t"});
  } else {
    reader.only_keys(layer, path, {"T", "tau", "albedo", "g", "mu_t", "interface"});
  }
  double tau = 0.0;
  AlbedoRgb rgb{};
  const bool has_t = layer.contains("T"), has_tau = layer.contains("tau");
  if (has_t && has_tau) reader.fail(path, "gives both \"T\" and \"tau\"; give one (T = exp(-tau))");
  if (!has_t && !has_tau) {
    reader.fail(path + ".T", "is missing (transparency T in [0, 1], or \"tau\": optical depth, a number or \"inf\")");
  }
  if (has_t) {
    tau = optical_depth_from_transparency(reader.parameter(layer["T"], path + ".T", "T"));
  } else if (layer["tau"].is_string() && layer["tau"].get<std::string>() == "inf") {
    tau = INFINITY;
  } else {
    if (layer["tau"].is_string())
      reader.fail(path + ".tau", "must be a number or \"inf\", not \"" + layer["tau"].get<std::string>() + "\"");
    tau = reader.parameter(layer["tau"], path + ".tau", "tau");
  }
  const Json& albedo = reader.required(layer, path, "albedo", "single-scattering albedo: a number or [r, g, b]");
  if (albedo.is_array()) {
    if (albedo.size() != 3)
      reader.fail(path + ".albedo", "must hold 3 numbers [r, g, b], not " + std::to_string(albedo.size()));
    for (std::size_t c = 0; c < 3; ++c) {
      rgb[c] = reader.parameter(albedo[c], path + ".albedo[" + std::to_string(c) + "]", "albedo");
    }
  } else {
    const double grey = reader.parameter(albedo, path + ".albedo", "albedo");
    rgb = {grey, grey, grey};
  }
  const double g = reader.required_parameter(layer, path, "g", "g");
  std::optional<double> extinction;
  if (layer.contains("mu_t")) extinction = reader.parameter(layer["mu_t"], path + ".mu_t", "mu-t");
  if (index == 0) {
    document.layer.tau = tau;
    document.layer.g = g;
    document.layer.extinction = extinction;
  } else {
    StackedLayer stacked{tau, rgb[0], g, std::nullopt, extinction};
    if (layer.contains("interface")) {
      const std::string at = path + ".interface";
      const Json& interface = reader.object(layer["interface"], at);
      reader.only_keys(interface, at, {"sigma", "eta"});
      LayerInterface parsed;
      parsed.sigma = reader.required_parameter(interface, at, "sigma", "sigma");
      const ParameterInfo& eta = interface_eta_info();
      parsed.eta = reader.parameter(
          reader.required(interface, at, "eta", std::string(eta.description) + ", a number in " + range_text(eta)),
          at + ".eta", eta);
      stacked.interface = parsed;
    }
    document.layer.below.push_back(stacked);
  }
  document.set_layer_albedo(index, rgb);
}

void read_bottom(const DocumentReader& reader, const Json& bottom, MaterialDocument& document) {
  reader.object(bottom, "bottom");
  const std::string type =
      reader.text(reader.required(bottom, "bottom", "type", "air, matched or lambert"), "bottom.type");
  if (type == "air") {
    reader.only_keys(bottom, "bottom", {"type", "sigma", "eta"});
    document.layer.bottom = Bottom{};
    if (bottom.contains("sigma")) {
      document.layer.bottom.sigma = reader.parameter(bottom["sigma"], "bottom.sigma", "bottom-sigma");
    }
    if (bottom.contains("eta")) document.layer.bottom.eta = reader.parameter(bottom["eta"], "bottom.eta", "bottom-eta");
  } else if (type == "matched") {
    reader.only_keys(bottom, "bottom", {"type"});
    document.layer.bottom = Bottom{BottomKind::Matched, std::nullopt, std::nullopt, 0.0};
  } else if (type == "lambert") {
    reader.only_keys(bottom, "bottom", {"type", "albedo"});
    const double albedo = reader.required_parameter(bottom, "bottom", "albedo", "lambert");
    document.layer.bottom = Bottom{BottomKind::Lambert, std::nullopt, std::nullopt, albedo};
  } else {
    reader.fail("bottom.type", "is \"" + type + "\", not one of air, matched, lambert");
  }
}

}  // namespace

Json material_json(const MaterialDocument& document) {
  Json json;
  json["format"] = kMaterialFormat;
  json["version"] = kMaterialVersion;
  if (!document.name.empty()) json["name"] = document.name;
  if (!document.description.empty()) json["description"] = document.description;
  const Material& m = document.layer;
  json["top"] = {{"sigma", m.sigma}, {"eta", m.eta}};
  json["microfacet"] = microfacet_model_name(m.microfacet);
  if (document.skin) {  // the skin makes the layers and the bottom
    Json skin = Json::object();
    for (const ParameterInfo& info : skin_parameter_table()) {
      skin[std::string(info.flag)] = skin_parameter(*document.skin, info.flag);
    }
    json["skin"] = skin;
    if (m.ordinates) json["ordinates"] = *m.ordinates;
    if (document.model) json["model"] = subsurface_model_name(*document.model);
    return json;
  }
  Json layers = Json::array();
  const std::vector<StackedLayer> stack = stack_layers(m);
  for (std::size_t i = 0; i < stack.size(); ++i) {
    Json layer = Json::object();
    if (const std::optional<double> transparency = exact_transparency(stack[i].tau)) {
      layer["T"] = *transparency;
    } else if (std::isinf(stack[i].tau)) {
      layer["tau"] = "inf";
    } else {
      layer["tau"] = stack[i].tau;
    }
    layer["albedo"] = albedo_json(document.layer_albedo(i));
    layer["g"] = stack[i].g;
    if (stack[i].extinction) layer["mu_t"] = *stack[i].extinction;
    if (stack[i].interface)
      layer["interface"] = {{"sigma", stack[i].interface->sigma}, {"eta", stack[i].interface->eta}};
    layers.push_back(layer);
  }
  json["layers"] = layers;
  switch (m.bottom.kind) {
    case BottomKind::Air:
      json["bottom"] = {{"type", "air"}, {"sigma", m.bottom_sigma()}, {"eta", m.bottom_eta()}};
      break;
    case BottomKind::Matched:
      json["bottom"] = {{"type", "matched"}};
      break;
    case BottomKind::Lambert:
      json["bottom"] = {{"type", "lambert"}, {"albedo", m.bottom.lambert_albedo}};
      break;
  }
  if (m.ordinates) json["ordinates"] = *m.ordinates;
  if (document.model) json["model"] = subsurface_model_name(*document.model);
  return json;
}

std::string material_json_text(const MaterialDocument& document) { return material_json(document).dump(2) + "\n"; }

nlohmann::ordered_json parse_json_document(std::string_view text, std::string_view source) {
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error& error) {
    // error.byte is the 1-based offset of the last byte read; line and column are counted here.
    const std::size_t end = std::min(error.byte == 0 ? 0 : error.byte - 1, text.size());
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + end, '\n'));
    const std::size_t line_start = text.rfind('\n', end == 0 ? 0 : end - 1);
    const std::size_t column = line_start == std::string_view::npos || end == 0 ? end + 1 : end - line_start;
    std::string reason = error.what();
    const std::size_t colon = reason.find(": ", reason.find("parse error"));
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    throw MaterialFileError(std::string(source) + ":" + std::to_string(line) + ":" + std::to_string(column) +
                            ": not valid JSON: " + reason);
  } catch (const Json::out_of_range& error) {
    // nlohmann's 406, "number overflow parsing '<token>'": a number past a double's range.
    const std::string what = error.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    const std::string token =
        open != std::string::npos && close > open ? text::quoted(what.substr(open + 1, close - open - 1)) + " " : "";
    throw MaterialFileError(std::string(source) + ": not valid JSON: the number " + token +
                            "is too large for a double (magnitude above 1.8e308)");
  }
}

MaterialDocument read_material_json(std::string_view text, std::string_view source) {
  return material_from_json(parse_json_document(text, source), source);
}

namespace {

// The "layers" list and the "bottom" of a layered material.
void read_layers_and_bottom(const DocumentReader& reader, const Json& json, MaterialDocument& document) {
  const Json& layers =
      reader.required(json, "", "layers", "a list of layers, each {\"T\" or \"tau\", \"albedo\", \"g\"}");
  if (!layers.is_array()) reader.fail("layers", "must be a list of layers, not " + type_name(layers));
  if (layers.empty()) reader.fail("layers", "holds 0 layers; a material has at least one");
  for (std::size_t i = 0; i < layers.size(); ++i) read_layer(reader, layers[i], i, document);

  read_bottom(reader, reader.required(json, "", "bottom", "{\"type\": \"air\" | \"matched\" | \"lambert\", ...}"),
              document);
}

// A skin material's "skin" block: any of the parameters of core/skin/skin_parameters.h, the rest at their defaults.
void read_skin(const DocumentReader& reader, const Json& block, MaterialDocument& document) {
  reader.object(block, "skin");
  std::vector<std::string_view> keys;
  for (const ParameterInfo& info : skin_parameter_table()) keys.push_back(info.flag);
  for (const auto& [key, value] : block.items()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string valid;
      for (const std::string_view k : keys) {
        if (!valid.empty()) valid += ", ";
        valid.append(k);
      }
      reader.fail("skin." + key, "is not a skin parameter; valid keys are " + valid);
    }
  }
  SkinParameters skin;
  for (const ParameterInfo& info : skin_parameter_table()) {
    const std::string key(info.flag);
    if (block.contains(key)) skin_parameter(skin, info.flag) = reader.parameter(block[key], "skin." + key, info);
  }
  document.skin = skin;
}

}  // namespace

MaterialDocument material_from_json(const Json& json, std::string_view source) {
  const DocumentReader reader(source);
  if (!json.is_object()) {
    throw MaterialFileError(std::string(source) + ": not a skinlayer material file (a JSON object with \"format\": \"" +
                            std::string(kMaterialFormat) + "\")");
  }
  const auto format = json.find("format");
  if (format == json.end() || !format->is_string() || format->get<std::string>() != kMaterialFormat) {
    throw MaterialFileError(std::string(source) + ": not a skinlayer material file (key \"format\" must be \"" +
                            std::string(kMaterialFormat) + "\")");
  }
  const Json& version =
      reader.required(json, "", "version", "the format's version, " + std::to_string(kMaterialVersion));
  if (!version.is_number_integer() && !version.is_number_unsigned()) {
    reader.fail("version", "must be a whole number, not " + type_name(version));
  }
  if (version.get<long long>() > kMaterialVersion) {
    throw MaterialFileError(std::string(source) + ": version " + std::to_string(version.get<long long>()) +
                            " is newer than this build of skinlayer reads (" + std::to_string(kMaterialVersion) + ")");
  }
  if (version.get<long long>() < 1)
    reader.fail("version", "must be 1, not " + std::to_string(version.get<long long>()));
  reader.only_keys(json, "",
                   {"format", "version", "name", "description", "top", "microfacet", "layers", "bottom", "skin",
                    "ordinates", "model"});

  MaterialDocument document;
  if (json.contains("name")) document.name = reader.text(json["name"], "name");
  if (json.contains("description")) document.description = reader.text(json["description"], "description");

  const Json& top = reader.object(reader.required(json, "", "top", "the top interface: {\"sigma\", \"eta\"}"), "top");
  reader.only_keys(top, "top", {"sigma", "eta"});
  document.layer.sigma = reader.required_parameter(top, "top", "sigma", "sigma");
  document.layer.eta = reader.required_parameter(top, "top", "eta", "eta");

  if (json.contains("skin")) {
    for (const char* made : {"layers", "bottom"}) {
      if (json.contains(made)) {
        reader.fail(made,
                    "is given with \"skin\", which makes the layers and the bottom from the chromophores; give"
                    " one of them");
      }
    }
    read_skin(reader, json["skin"], document);
  } else {
    read_layers_and_bottom(reader, json, document);
  }
  if (json.contains("ordinates")) {
    const double ordinates = reader.parameter(json["ordinates"], "ordinates", "ordinates");
    if (ordinates != std::floor(ordinates)) reader.fail("ordinates", "must be a whole number");
    document.layer.ordinates = static_cast<int>(ordinates);
  }
  // A file written before the field existed was solved with one microfacet meeting, and reads so, to look as it did.
  document.layer.microfacet = MicrofacetModel::Single;
  if (json.contains("microfacet")) {
    const std::string name = reader.text(json["microfacet"], "microfacet");
    const std::optional<MicrofacetModel> model = parse_microfacet_model(name);
    if (!model) reader.fail("microfacet", "is \"" + name + "\", not one of multiple, single");
    document.layer.microfacet = *model;
  }
  if (json.contains("model")) {
    const std::string name = reader.text(json["model"], "model");
    document.model = parse_subsurface_model(name);
    if (!document.model) reader.fail("model", "is \"" + name + "\", not one of stam, lambert, hk");
  }
  try {
    validate(document.layer);
  } catch (const ParameterError& error) {
    throw MaterialFileError(std::string(source) + ": " + error.what());
  }
  return document;
}

}  // namespace skinlayer
