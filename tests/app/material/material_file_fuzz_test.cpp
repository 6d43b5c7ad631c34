// Fuzz-style tests of the material file readers, in-process so that the sanitizer build (./setup.sh test) sees every
// byte they read: read_material_json on presets with bytes flipped, inserted and deleted and with values swapped for
// extreme ones, and material_from_picture on damaged PNGs. Each call must return a valid material that writes and
// reads back to itself, or throw MaterialFileError with one line naming the source. Fixed seeds.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "app/material/material_json.h"
#include "app/material/picture_metadata.h"
#include "app/material/png_codec.h"
#include "app/material/presets.h"
#include "core/material.h"

namespace skinlayer {
namespace {

using Random = std::mt19937_64;

std::size_t below(Random& random, std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
}

std::string mutated(Random& random, std::string text) {
  const std::size_t edits = 1 + below(random, 4);
  const std::string alphabet = "{}[]\":,0123456789.eE+-tnfalsrue \n\t\\\xff\x01";
  for (std::size_t e = 0; e < edits && !text.empty(); ++e) {
    const std::size_t at = below(random, text.size());
    switch (below(random, 3)) {
      case 0:
        text[at] = alphabet[below(random, alphabet.size())];
        break;
      case 1:
        text.insert(at, 1, alphabet[below(random, alphabet.size())]);
        break;
      default:
        text.erase(at, 1 + below(random, 8));
        break;
    }
  }
  return text;
}

// A JSON value of any type, numbers at the edges of the parameters' ranges.
nlohmann::ordered_json random_value(Random& random) {
  static const std::vector<double> numbers = {0,     -0.0, 1,   -1,  0.05, 0.0499999, 2.5,    2.5000001, 0.95,
                                              -0.95, 0.96, 256, 3.5, 4,    1e308,     -1e308, 5e-324,    1e-9};
  switch (below(random, 7)) {
    case 0:
      return numbers[below(random, numbers.size())];
    case 1:
      return "inf";
    case 2:
      return nlohmann::ordered_json::array({0.5, 0.5, 0.5});
    case 3:
      return nlohmann::ordered_json::array({0.5, "x"});
    case 4:
      return nlohmann::ordered_json::object();
    case 5:
      return nullptr;
    default:
      return static_cast<long long>(below(random, 600)) - 100;
  }
}

// Sets a random leaf of the document (or adds a key) to a random value.
void swap_value(Random& random, nlohmann::ordered_json& json) {
  nlohmann::ordered_json* node = &json;
  for (int depth = 0; depth < 4 && (node->is_object() || node->is_array()) && !node->empty(); ++depth) {
    auto it = node->begin();
    std::advance(it, static_cast<long>(below(random, node->size())));
    if (below(random, 3) == 0) break;
    node = &*it;
  }
  if (node->is_object() && below(random, 4) == 0) {
    (*node)["extra"] = random_value(random);
  } else {
    *node = random_value(random);
  }
}

// The reader's contract for one input; false (with a failure recorded) when broken.
bool check_read(const std::string& text) {
  try {
    const MaterialDocument document = read_material_json(text, "fuzz.json");
    validate(document.layer);
    const MaterialDocument again = read_material_json(material_json_text(document), "again.json");
    const bool same = again.layer.sigma == document.layer.sigma && again.layer.tau == document.layer.tau &&
                      again.albedo_rgb == document.albedo_rgb && again.layer.g == document.layer.g &&
                      again.layer.bottom.kind == document.layer.bottom.kind &&
                      again.layer.bottom_sigma() == document.layer.bottom_sigma();
    EXPECT_TRUE(same) << "did not read back: " << text;
    return same;
  } catch (const MaterialFileError& error) {
    const std::string message = error.what();
    const bool ok = message.rfind("fuzz.json", 0) == 0 && message.find('\n') == std::string::npos;
    EXPECT_TRUE(ok) << "message \"" << message << "\" for " << text;
    return ok;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "threw " << typeid(error).name() << " (" << error.what() << ") for " << text;
    return false;
  }
}

TEST(MaterialFileFuzz, MutatedPresetsReadOrFailWithOneLine) {
  Random random(0x5eed0011);
  std::vector<std::string> texts;
  for (const PresetInfo& preset : preset_list()) texts.push_back(material_json_text(preset_material(preset.name)));
  int failures = 0, read = 0;
  for (int trial = 0; trial < 6000 && failures < 10; ++trial) {
    std::string text = texts[below(random, texts.size())];
    if (trial % 2 == 0) {
      text = mutated(random, text);
    } else {
      nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
      for (std::size_t k = 0, n = 1 + below(random, 3); k < n; ++k) swap_value(random, json);
      text = json.dump();
    }
    try {
      read_material_json(text, "fuzz.json");
      ++read;
    } catch (...) {
    }
    if (!check_read(text)) ++failures;
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(read, 300) << "enough inputs stayed valid for the round trip to be checked";
}

TEST(MaterialFileFuzz, DamagedPicturesFailWithOneLine) {
  Random random(0x5eed0012);
  std::vector<std::uint8_t> pixels(8 * 8 * 4, 128);
  const std::string png = encode_png_rgba8(
      8, 8, pixels, {picture_metadata(preset_material("skin-fair"), nlohmann::ordered_json::object())});
  int failures = 0;
  for (int trial = 0; trial < 3000 && failures < 10; ++trial) {
    std::string bytes = png;
    if (trial % 3 == 0) {
      bytes.resize(below(random, bytes.size()));
    } else {
      for (std::size_t k = 0, n = 1 + below(random, 6); k < n; ++k) {
        bytes[below(random, bytes.size())] = static_cast<char>(below(random, 256));
      }
    }
    try {
      const MaterialDocument document = material_from_picture(bytes, "fuzz.png");
      validate(document.layer);
    } catch (const MaterialFileError& error) {
      const std::string message = error.what();
      if (message.rfind("fuzz.png", 0) != 0 || message.find('\n') != std::string::npos) {
        ADD_FAILURE() << "message \"" << message << "\"";
        ++failures;
      }
    } catch (const std::exception& error) {
      ADD_FAILURE() << "threw " << typeid(error).name() << " (" << error.what() << ")";
      ++failures;
    }
  }
  EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace skinlayer
