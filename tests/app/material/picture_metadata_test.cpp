// Pictures that remember (app/material/picture_metadata.h, png_codec.h): the PNG holds its pixels and its
// material, libpng reads both back, and a PNG without the chunk, or a damaged one, gets a one-line error.
#include "app/material/picture_metadata.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/material/material_json.h"
#include "app/material/png_codec.h"

namespace skinlayer {
namespace {

std::vector<std::uint8_t> gradient(int width, int height) {
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      rgba.insert(rgba.end(), {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 11),
                               static_cast<std::uint8_t>(x ^ y), 255});
    }
  }
  return rgba;
}

MaterialDocument skin() {
  MaterialDocument document;
  document.name = "skin";
  document.layer.sigma = 0.35;
  document.albedo_rgb = {0.95, 0.7, 0.55};
  document.layer.albedo = 0.95;
  document.model = SubsurfaceModel::Stam;
  return document;
}

TEST(PictureMetadata, ThePngCarriesItsMaterialAndSettings) {
  const nlohmann::ordered_json settings = {{"light_theta", 45.0}, {"view", "both"}};
  const std::string png = encode_png_rgba8(16, 9, gradient(16, 9), {picture_metadata(skin(), settings)});
  ASSERT_TRUE(is_png(png));
  const MaterialDocument read = material_from_picture(png, "shot.png");
  EXPECT_EQ(read.name, "skin");
  EXPECT_EQ(read.layer.sigma, 0.35);
  EXPECT_EQ(read.albedo_rgb, skin().albedo_rgb);
  const std::optional<std::string> chunk = read_png_text(png, kPictureChunkKeyword);
  ASSERT_TRUE(chunk);
  const nlohmann::json json = nlohmann::json::parse(*chunk);
  EXPECT_EQ(json["format"], "skinlayer-picture");
  EXPECT_EQ(json["settings"]["light_theta"], 45.0);
  EXPECT_EQ(json["material"], nlohmann::json::parse(material_json(skin()).dump())) << "the material file, as is";
}

TEST(PictureMetadata, APngWithoutTheChunkOrDamagedSaysSo) {
  const std::string plain = encode_png_rgba8(4, 4, gradient(4, 4));
  EXPECT_FALSE(read_png_text(plain, kPictureChunkKeyword));
  try {
    material_from_picture(plain, "plain.png");
    ADD_FAILURE() << "a PNG without a material was read";
  } catch (const MaterialFileError& error) {
    EXPECT_NE(std::string(error.what()).find("plain.png: a PNG without a material"), std::string::npos) << error.what();
  }
  const std::string full = encode_png_rgba8(4, 4, gradient(4, 4), {picture_metadata(skin(), {})});
  const std::string truncated = full.substr(0, 40);  // the signature and part of the header
  EXPECT_THROW(material_from_picture(truncated, "cut.png"), MaterialFileError);
  std::string corrupt = full;
  corrupt[20] = static_cast<char>(corrupt[20] ^ 0x55);  // inside IHDR: its CRC no longer matches
  EXPECT_THROW(material_from_picture(corrupt, "bad.png"), MaterialFileError);
  EXPECT_THROW(encode_png_rgba8(4, 4, gradient(3, 4)), std::runtime_error) << "pixels that do not fill the image";
}

// Found by fuzzing (tests/fuzz): a text chunk whose length field says 2 GB, in a file of a few hundred bytes. libpng
// allocates a chunk before it reads it; the reader caps every allocation, so the file is refused at once.
TEST(PictureMetadata, AChunkLengthBeyondTheFileIsRefusedWithoutAllocatingIt) {
  std::string png = encode_png_rgba8(4, 4, gradient(4, 4), {picture_metadata(skin(), {})});
  const std::size_t chunk = png.find("iTXt");
  ASSERT_NE(chunk, std::string::npos);
  for (int n = 0; n < 4; ++n) png[chunk - 4 + n] = "\x7a\x00\x00\x00"[n];  // 2046820352 bytes, big-endian
  try {
    material_from_picture(png, "huge.png");
    ADD_FAILURE() << "a chunk of 2 GB was read";
  } catch (const MaterialFileError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("huge.png: ", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace skinlayer
