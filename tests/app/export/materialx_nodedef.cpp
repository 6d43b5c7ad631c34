#include "tests/app/export/materialx_nodedef.h"

#include <charconv>
#include <pugixml.hpp>
#include <set>
#include <stdexcept>

namespace skinlayer::test {
namespace {

std::size_t components(const std::string& type) {
  if (type == "float" || type == "integer" || type == "boolean") return 1;
  if (type == "color3" || type == "vector3") return 3;
  if (type == "color4" || type == "vector4") return 4;
  if (type == "vector2") return 2;
  return 0;
}

// A MaterialX value: comma-separated numbers, spaces allowed around them.
std::optional<std::vector<double>> numbers(const std::string& text) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    std::size_t a = start, b = end;
    while (a < b && text[a] == ' ') ++a;
    while (b > a && text[b - 1] == ' ') --b;
    double value = 0.0;
    const auto [ptr, error] = std::from_chars(text.data() + a, text.data() + b, value);
    if (a == b || error != std::errc() || ptr != text.data() + b) return std::nullopt;
    values.push_back(value);
    start = end + 1;
  }
  return values;
}

}  // namespace

NodeDefinition read_node_definition(const std::string& path, const std::string& name) {
  pugi::xml_document xml;
  if (!xml.load_file(path.c_str())) throw std::runtime_error("cannot read " + path);
  const pugi::xml_node nodedef = xml.child("materialx").find_child_by_attribute("nodedef", "name", name.c_str());
  if (!nodedef) throw std::runtime_error(path + " has no nodedef " + name);
  NodeDefinition definition;
  definition.node = nodedef.attribute("node").value();
  definition.output_type = nodedef.child("output").attribute("type").value();
  for (const pugi::xml_node input : nodedef.children("input")) {
    NodeInput in;
    in.type = input.attribute("type").value();
    if (const pugi::xml_attribute lo = input.attribute("uimin")) in.uimin = numbers(lo.value());
    if (const pugi::xml_attribute hi = input.attribute("uimax")) in.uimax = numbers(hi.value());
    definition.inputs[input.attribute("name").value()] = in;
  }
  if (definition.node.empty() || definition.inputs.empty())
    throw std::runtime_error(name + " in " + path + " is empty");
  return definition;
}

std::vector<std::string> materialx_problems(const std::string& text, const NodeDefinition& definition,
                                            const std::string& version) {
  std::vector<std::string> problems;
  pugi::xml_document xml;
  const pugi::xml_parse_result parsed = xml.load_string(text.c_str());
  if (!parsed) return {std::string("not XML: ") + parsed.description()};
  const pugi::xml_node root = xml.child("materialx");
  if (!root) return {"no <materialx> root"};
  if (std::string(root.attribute("version").value()) != version)
    problems.push_back("materialx version is not " + version);
  std::set<std::string> shaders;
  for (const pugi::xml_node node : root.children(definition.node.c_str())) {
    const std::string node_name = node.attribute("name").value();
    shaders.insert(node_name);
    if (definition.output_type != node.attribute("type").value()) {
      problems.push_back(node_name + ": type is not " + definition.output_type);
    }
    std::set<std::string> seen;
    for (const pugi::xml_node input : node.children("input")) {
      const std::string name = input.attribute("name").value(), type = input.attribute("type").value();
      const std::string where = node_name + "." + name;
      if (!seen.insert(name).second) problems.push_back(where + ": given twice");
      const auto known = definition.inputs.find(name);
      if (known == definition.inputs.end()) {
        problems.push_back(where + ": no such input of " + definition.node);
        continue;
      }
      if (type != known->second.type) problems.push_back(where + ": type " + type + ", defined " + known->second.type);
      const std::optional<std::vector<double>> values = numbers(input.attribute("value").value());
      if (!values || values->size() != components(known->second.type)) {
        problems.push_back(where + ": value '" + input.attribute("value").value() + "' is not a " + known->second.type);
        continue;
      }
      for (std::size_t k = 0; k < values->size(); ++k) {
        const auto& lo = known->second.uimin;
        const auto& hi = known->second.uimax;
        if (lo && (*values)[k] < (*lo)[std::min(k, lo->size() - 1)]) problems.push_back(where + ": below its uimin");
        if (hi && (*values)[k] > (*hi)[std::min(k, hi->size() - 1)]) problems.push_back(where + ": above its uimax");
      }
      if (input.attribute("unit") &&
          (type != "float" || std::string(input.attribute("unittype").value()) != "distance")) {
        problems.push_back(where + ": a unit without unittype distance on a float");
      }
    }
  }
  if (shaders.empty()) problems.push_back("no " + definition.node + " node");
  const pugi::xml_node material = root.child("surfacematerial");
  if (!material) problems.push_back("no surfacematerial");
  for (const pugi::xml_node m : root.children("surfacematerial")) {
    const pugi::xml_node surface = m.find_child_by_attribute("input", "name", "surfaceshader");
    if (!surface || !shaders.count(surface.attribute("nodename").value())) {
      problems.push_back(std::string(m.attribute("name").value()) + ": its surfaceshader names no " + definition.node);
    }
  }
  return problems;
}

}  // namespace skinlayer::test
