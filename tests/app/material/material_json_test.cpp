// Material files (app/material/material_json.h): what `material` writes reads back bit for bit, and every way a
// file can be wrong gets one line that names the file and the key (or line:column).
#include "app/material/material_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/text/quoted.h"
#include "core/material.h"

namespace skinlayer {
namespace {

void expect_same(const MaterialDocument& a, const MaterialDocument& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.layer.sigma, b.layer.sigma);
  EXPECT_EQ(a.layer.eta, b.layer.eta);
  EXPECT_EQ(a.layer.tau, b.layer.tau);
  EXPECT_EQ(a.layer.albedo, b.layer.albedo);
  EXPECT_EQ(a.layer.g, b.layer.g);
  EXPECT_EQ(a.layer.bottom.kind, b.layer.bottom.kind);
  EXPECT_EQ(a.layer.bottom_sigma(), b.layer.bottom_sigma());
  EXPECT_EQ(a.layer.bottom_eta(), b.layer.bottom_eta());
  EXPECT_EQ(a.layer.bottom.lambert_albedo, b.layer.bottom.lambert_albedo);
  EXPECT_EQ(a.layer.ordinates, b.layer.ordinates);
  EXPECT_EQ(a.layer.extinction, b.layer.extinction);
  EXPECT_EQ(a.albedo_rgb, b.albedo_rgb);
  EXPECT_EQ(a.layer.below, b.layer.below);
  EXPECT_EQ(a.below_rgb, b.below_rgb);
  EXPECT_EQ(a.model, b.model);
}

std::vector<MaterialDocument> assorted_documents() {
  std::vector<MaterialDocument> documents(10);
  // Physical lengths: the first layer's extinction, and a stacked layer's beside one without.
  documents[9].layer.extinction = 0.1 * 3;
  documents[9].layer.below = {{0.5, 1.0, 0.3, std::nullopt, 7.25}, {INFINITY, 1.0, 0.6, std::nullopt, std::nullopt}};
  documents[9].set_layer_albedo(1, {1.0, 1.0, 1.0});
  documents[9].set_layer_albedo(2, {1.0, 1.0, 1.0});
  // Stacks: RGB per layer, an interface between layers, a semi-infinite last layer, a depth no T reads back.
  documents[7].layer.below = {{0.1, 1.0, 0.3, LayerInterface{0.25, 0.8}}, {INFINITY, 1.0, -0.2, std::nullopt}};
  documents[7].set_layer_albedo(1, {0.9, 0.8, 0.7});
  documents[7].set_layer_albedo(2, {0.5, 0.5, 0.5});
  documents[8].layer.below = {{optical_depth_from_transparency(0.3), 0.7, 0.9, LayerInterface{1.0, 1.0}}};
  documents[8].set_layer_albedo(1, {0.7, 0.7, 0.7});
  documents[1].name = "skin «test»";
  documents[1].description = "UTF-8 survives: σ, η, Ω";
  documents[1].albedo_rgb = {0.95, 0.7, 0.55};
  documents[1].layer.albedo = 0.95;
  documents[2].layer.tau = INFINITY;
  documents[3].layer.tau = 0.1;  // no T reads back to exactly this depth: "tau"
  documents[3].layer.bottom = parse_bottom("lambert:0.35");
  documents[4].layer.bottom = parse_bottom("matched");
  documents[4].layer.ordinates = 48;
  documents[4].model = SubsurfaceModel::HanrahanKrueger;
  documents[5].layer.bottom.sigma = 0.1;
  documents[5].layer.bottom.eta = 1.2;
  documents[5].layer.sigma = 0.05;
  documents[5].layer.g = -0.95;
  documents[6].layer.tau = optical_depth_from_transparency(0.1);
  return documents;
}

TEST(MaterialJson, WhatIsWrittenReadsBackBitForBit) {
  for (const MaterialDocument& document : assorted_documents()) {
    const std::string text = material_json_text(document);
    expect_same(read_material_json(text, "test.json"), document);
  }
  // T with the fewest digits that read back exactly; the semi-infinite layer as T 0; tau where no T reads back.
  const std::vector<MaterialDocument> documents = assorted_documents();
  EXPECT_NE(material_json_text(documents[6]).find("\"T\": 0.1,"), std::string::npos);
  EXPECT_NE(material_json_text(documents[2]).find("\"T\": 0.0"), std::string::npos);
  EXPECT_NE(material_json_text(documents[3]).find("\"tau\": 0.1,"), std::string::npos);
  EXPECT_NE(material_json_text(documents[1]).find("[\n"), std::string::npos) << "an RGB albedo is a list";
  const nlohmann::ordered_json stack = material_json(documents[7]);
  ASSERT_EQ(stack["layers"].size(), 3u);
  EXPECT_FALSE(stack["layers"][0].contains("interface"));
  EXPECT_EQ(stack["layers"][1]["interface"]["eta"], 0.8);
  EXPECT_EQ(stack["layers"][2]["T"], 0.0);
  // A layer's extinction is its "mu_t"; a layer without one has no such key.
  const nlohmann::ordered_json lengths = material_json(documents[9]);
  EXPECT_EQ(lengths["layers"][0]["mu_t"], 0.1 * 3);
  EXPECT_EQ(lengths["layers"][1]["mu_t"], 7.25);
  EXPECT_FALSE(lengths["layers"][2].contains("mu_t"));
  EXPECT_FALSE(material_json(documents[0])["layers"][0].contains("mu_t"));
}

// A skin material: its "skin" block in place of the layers and the bottom, every parameter explicit.
TEST(MaterialJson, ASkinReadsBackWithEveryParameter) {
  MaterialDocument document;
  document.name = "freckled";
  document.layer.sigma = 0.35;
  document.layer.ordinates = 40;
  SkinParameters skin;
  skin.melanin = 0.123;
  skin.eumelanin = 0.4;
  skin.blood = 0.0375;
  skin.oxygenation = 0.6;
  skin.epidermis = 0.1;
  skin.scattering = 1.3;
  document.skin = skin;
  const nlohmann::ordered_json json = material_json(document);
  EXPECT_FALSE(json.contains("layers"));
  EXPECT_FALSE(json.contains("bottom"));
  EXPECT_EQ(json["skin"].size(), 6u);
  const MaterialDocument back = read_material_json(material_json_text(document), "skin.json");
  ASSERT_TRUE(back.skin.has_value());
  EXPECT_EQ(*back.skin, skin);
  EXPECT_EQ(back.layer.sigma, 0.35);
  EXPECT_EQ(back.layer.ordinates, 40);
  // Omitted keys take their defaults.
  const MaterialDocument minimal = read_material_json(
      R"({"format": "skinlayer-material", "version": 1, "top": {"sigma": 0.5, "eta": 1.4}, "skin": {"blood": 0.01}})",
      "minimal.json");
  SkinParameters expected;
  expected.blood = 0.01;
  EXPECT_EQ(*minimal.skin, expected);
}

TEST(MaterialJson, EveryValueIsExplicitAndTheBottomStatesItsInterface) {
  const nlohmann::ordered_json json = material_json(MaterialDocument{});
  EXPECT_EQ(json["format"], "skinlayer-material");
  EXPECT_EQ(json["version"], 1);
  EXPECT_EQ(json["top"]["sigma"], 0.5);
  EXPECT_EQ(json["bottom"]["sigma"], 0.5) << "air's sigma written although the material leaves it to the top's";
  EXPECT_EQ(json["bottom"]["eta"], 1.4);
  EXPECT_EQ(json["layers"].size(), 1u);
  EXPECT_EQ(json["layers"][0]["T"], 0.2);
}

TEST(MaterialJson, TauInfAndMinimalFilesRead) {
  const MaterialDocument document = read_material_json(R"({"format": "skinlayer-material", "version": 1,
    "top": {"sigma": 0.3, "eta": 1.5}, "layers": [{"tau": "inf", "albedo": [0.9, 0.8, 0.7], "g": 0.5}],
    "bottom": {"type": "air"}, "model": "lambert"})",
                                                       "min.json");
  EXPECT_TRUE(std::isinf(document.layer.tau));
  EXPECT_EQ(document.albedo_rgb[2], 0.7);
  EXPECT_EQ(document.layer.albedo, 0.9);
  EXPECT_FALSE(document.layer.bottom.sigma.has_value()) << "air without sigma: the top's, as --bottom air";
  EXPECT_EQ(document.model, SubsurfaceModel::Lambert);
}

// A file written before the microfacet field existed was made under Stam's single-scattering interfaces and reads
// so, to look as it did; skinlayer writes the field, and a material made from flags takes the default, multiple.
TEST(MaterialJson, AFileWithoutTheMicrofacetFieldReadsAsSingle) {
  const std::string older = R"({"format": "skinlayer-material", "version": 1, "top": {"sigma": 0.5, "eta": 1.4},
    "layers": [{"T": 0.2, "albedo": 1, "g": 0.8}], "bottom": {"type": "air"}})";
  EXPECT_EQ(read_material_json(older, "old.json").layer.microfacet, MicrofacetModel::Single);
  std::string newer = older;
  newer.insert(newer.find("\"layers\""), "\"microfacet\": \"multiple\", ");
  EXPECT_EQ(read_material_json(newer, "new.json").layer.microfacet, MicrofacetModel::Multiple);
  MaterialDocument made;
  ASSERT_EQ(made.layer.microfacet, MicrofacetModel::Multiple);
  const std::string written = material_json_text(made);
  EXPECT_NE(written.find("\"microfacet\": \"multiple\""), std::string::npos) << written;
  EXPECT_EQ(read_material_json(written, "written.json").layer.microfacet, MicrofacetModel::Multiple);
  made.layer.microfacet = MicrofacetModel::Single;
  EXPECT_EQ(read_material_json(material_json_text(made), "single.json").layer.microfacet, MicrofacetModel::Single);
}

struct BadFile {
  std::string text;
  std::vector<std::string> message_has;  // each must appear in the one-line message
};

// A valid file with one replacement made.
std::string valid_with(const std::string& from, const std::string& to) {
  std::string text = R"({
  "format": "skinlayer-material",
  "version": 1,
  "top": {"sigma": 0.5, "eta": 1.4},
  "layers": [{"T": 0.2, "albedo": 1, "g": 0.8}],
  "bottom": {"type": "air", "sigma": 0.5, "eta": 1.4}
})";
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(MaterialJson, EachKindOfErrorIsOneLineNamingTheFileAndTheKey) {
  const std::vector<BadFile> cases = {
      {valid_with("\"eta\": 1.4}", "\"eta\" 1.4}"), {"bad.json:4:", "not valid JSON"}},  // line 4
      {"", {"bad.json:1:1", "not valid JSON"}},
      {valid_with("\"sigma\": 0.5, \"eta\": 1.4}", "\"sigma\": 0.5, \"etaa\": 1.4}"),
       {"bad.json", "unknown key \"top.etaa\"", "sigma, eta"}},
      {valid_with("\"version\": 1,", "\"version\": 1, \"colour\": 3,"), {"unknown key \"colour\"", "layers"}},
      // A newline inside a key (found by the mutation test): printed as '?', so the message stays one line.
      {valid_with("\"version\": 1,", "\"version\": 1, \"na\\nme\": 3,"), {"unknown key \"na?me\"", "layers"}},
      {valid_with("\"g\": 0.8", "\"g\": \"0.8\""), {"bad.json", "\"layers[0].g\"", "must be a number", "a string"}},
      {valid_with("\"g\": 0.8", "\"g\": 1.2"), {"bad.json", "\"layers[0].g\"", "out of range", "[-0.95, 0.95]"}},
      {valid_with("\"g\": 0.8", "\"g\": 0.8, \"mu_t\": -3"),
       {"bad.json", "\"layers[0].mu_t\"", "out of range", "[1e-06, 1000000]", "1/mm"}},
      {valid_with("\"g\": 0.8", "\"g\": 0.8, \"mu_t\": \"12 /mm\""), {"\"layers[0].mu_t\"", "must be a number"}},
      {valid_with(", \"g\": 0.8", ""), {"bad.json", "\"layers[0].g\"", "missing"}},
      {valid_with("\"T\": 0.2, ", ""), {"\"layers[0].T\"", "missing", "tau"}},
      {valid_with("\"T\": 0.2", "\"T\": 0.2, \"tau\": 1"), {"\"layers[0]\"", "both"}},
      {valid_with("\"version\": 1", "\"version\": 2"), {"bad.json", "version 2", "newer"}},
      {valid_with("\"version\": 1", "\"version\": 0"), {"\"version\"", "must be 1"}},
      {valid_with("\"skinlayer-material\"", "\"something-else\""), {"bad.json", "not a skinlayer material file"}},
      {valid_with("\"type\": \"air\"", "\"type\": \"wood\""), {"\"bottom.type\"", "wood", "matched"}},
      {valid_with("\"version\": 1,", "\"version\": 1, \"skin\": {\"melanin\": 0.1},"),
       {"\"layers\"", "\"skin\"", "one of them"}},
      {valid_with("  \"layers\": [{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}],\n  \"bottom\": {\"type\": \"air\", "
                  "\"sigma\": 0.5, \"eta\": 1.4}",
                  "  \"skin\": {\"blood\": 0.3}"),
       {"bad.json", "\"skin.blood\"", "out of range", "[0, 0.2]"}},
      {valid_with("  \"layers\": [{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}],\n  \"bottom\": {\"type\": \"air\", "
                  "\"sigma\": 0.5, \"eta\": 1.4}",
                  "  \"skin\": {\"freckles\": 1}"),
       {"bad.json", "\"skin.freckles\"", "melanin, eumelanin"}},
      {valid_with("\"type\": \"air\", \"sigma\": 0.5, \"eta\": 1.4", "\"type\": \"lambert\""),
       {"\"bottom.albedo\"", "missing"}},
      {valid_with("\"type\": \"air\", \"sigma\": 0.5, \"eta\": 1.4", "\"type\": \"matched\", \"sigma\": 1"),
       {"unknown key \"bottom.sigma\"", "type"}},
      {valid_with("\"albedo\": 1", "\"albedo\": [1, 0.5]"), {"\"layers[0].albedo\"", "3 numbers"}},
      {valid_with("\"albedo\": 1", "\"albedo\": [1, 0.5, 1.5]"), {"\"layers[0].albedo[2]\"", "out of range"}},
      {valid_with("[{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}]", "[]"), {"\"layers\"", "holds 0 layers"}},
      {valid_with("\"layers\": [{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}]", "\"layers\": {}"),
       {"\"layers\"", "must be a list"}},
      {valid_with("\"top\": {\"sigma\": 0.5, \"eta\": 1.4},", ""), {"\"top\"", "missing"}},
      {valid_with("\"version\": 1,", "\"version\": 1, \"ordinates\": 10.5,"), {"\"ordinates\"", "whole number"}},
      {valid_with("\"version\": 1,", "\"version\": 1, \"model\": \"phong\","), {"\"model\"", "phong", "stam"}},
      {valid_with("\"version\": 1,", "\"version\": 1, \"microfacet\": \"double\","),
       {"\"microfacet\"", "double", "multiple, single"}},
      {"[1, 2, 3]", {"bad.json", "not a skinlayer material file"}},
      // Stacks: an interface above the first layer, a semi-infinite layer above another, an interface out of range.
      {valid_with("\"g\": 0.8}]", "\"g\": 0.8, \"interface\": {\"sigma\": 0.3, \"eta\": 1.1}}]"),
       {"unknown key \"layers[0].interface\""}},
      {valid_with("[{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}]",
                  "[{\"T\": 0, \"albedo\": 1, \"g\": 0.8}, {\"T\": 0.5, \"albedo\": 1, \"g\": 0}]"),
       {"bad.json", "layer 1", "only for the last layer"}},
      {valid_with("[{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}]",
                  "[{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}, {\"T\": 0.5, \"albedo\": 1, \"g\": 0, "
                  "\"interface\": {\"sigma\": 0.3, \"eta\": 3}}]"),
       {"\"layers[1].interface.eta\"", "eta = 3", "[0.4, 2.5]"}},
      {valid_with("[{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}]",
                  "[{\"T\": 0.2, \"albedo\": 1, \"g\": 0.8}, {\"T\": 0.5, \"albedo\": 1, \"g\": 0, "
                  "\"interface\": {\"sigma\": 0.3}}]"),
       {"\"layers[1].interface.eta\"", "missing"}},
      // Found by fuzzing (tests/fuzz): a number past a double's range, which nlohmann reports apart from syntax.
      {valid_with("\"g\": 0.8", "\"g\": 5e4444"), {"bad.json", "not valid JSON", "'5e4444'", "too large"}},
  };
  for (const BadFile& bad : cases) {
    try {
      read_material_json(bad.text, "bad.json");
      ADD_FAILURE() << "accepted: " << bad.text;
    } catch (const MaterialFileError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(message.rfind("bad.json", 0), 0u) << message;
      for (const std::string& part : bad.message_has) EXPECT_NE(message.find(part), std::string::npos) << message;
    }
  }
}

// Found by fuzzing (tests/fuzz): bytes of the file that a message quotes are made printable, as control
// characters and ill-formed UTF-8 would break the line or Python's str of the message.
TEST(MaterialJson, MessagesQuoteTheFileAsPrintableUtf8) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {valid_with("\"version\": 1,", "\"version\": 1, \"\xc3\xa9t\xc3\xa9\": 3,"), "unknown key \"\xc3\xa9t\xc3\xa9\""},
      {valid_with("\"version\": 1,", "\"version\": 1, \"a\x7f\": 3,"), "unknown key \"a?\""},  // DEL is valid JSON
      {valid_with("\"version\": 1,", "\"version\": 1, \"a\xff\xfe\": 3,"), "not valid JSON"},
      {valid_with("\"type\": \"air\"", "\"type\": \"a\\u0001b\""), "\"a?b\""},
  };
  for (const auto& [text, part] : cases) {
    try {
      read_material_json(text, "bad.json");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const MaterialFileError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(part), std::string::npos) << message;
      EXPECT_EQ(text::printable(message), message) << "not printable UTF-8: " << message;
    }
  }
}

}  // namespace
}  // namespace skinlayer
