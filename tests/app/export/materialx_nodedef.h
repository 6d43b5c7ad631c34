// A MaterialX node definition read with pugixml, and a document's nodes checked against it: the check the OpenPBR
// export's test runs in place of MaterialX's own validator, which Debian 12 does not package.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace skinlayer::test {

struct NodeInput {
  std::string type;                                 // "float", "color3", "boolean", "vector3", ...
  std::optional<std::vector<double>> uimin, uimax;  // per component, where the definition gives them
};

struct NodeDefinition {
  std::string node;  // the node's category, e.g. "open_pbr_surface"
  std::string output_type;
  std::map<std::string, NodeInput> inputs;
};

// The <nodedef name="..."> in the file; throws std::runtime_error naming what is missing.
NodeDefinition read_node_definition(const std::string& path, const std::string& name);

// What is wrong with a MaterialX document's text, one line each (empty when nothing): its root and version, every
// node of the definition's category (its type the definition's output; each input known, of the defined type, with
// a value that parses as that type within uimin and uimax; a unit only with unittype "distance" on a float), and
// every surfacematerial's surfaceshader input naming such a node.
std::vector<std::string> materialx_problems(const std::string& text, const NodeDefinition& definition,
                                            const std::string& version);

}  // namespace skinlayer::test
