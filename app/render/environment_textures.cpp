#include "app/render/environment_textures.h"

#include <algorithm>
#include <utility>

namespace skinlayer {
namespace {

// A float texture of one channel (R32F) or three (RGB32F), nearest-filtered unless `mipmapped` (then trilinear and
// wrapping in u, for the radiance). Returns the bytes it holds.
std::size_t upload_float_texture(GLuint texture, int width, int height, int channels, const float* texels,
                                 bool mipmapped = false) {
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, channels == 1 ? GL_R32F : GL_RGB32F, width, height, 0, channels == 1 ? GL_RED : GL_RGB,
               GL_FLOAT, texels);
  std::size_t bytes = static_cast<std::size_t>(width) * height * channels * sizeof(float);
  if (mipmapped) {
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    bytes += bytes / 3;  // the mip chain: 1/4 + 1/16 + ... of the base
  } else {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  return bytes;
}

}  // namespace

EnvironmentTextures upload_environment_textures(const EnvironmentMap& map) {
  const EnvironmentDistribution distribution = environment_distribution(map);
  EnvironmentTextures textures{
      gl::create_texture(), gl::create_texture(), gl::create_texture(), gl::create_texture(), map.width, map.height, 0};
  textures.bytes =
      upload_float_texture(textures.radiance.get(), map.width, map.height, 3, map.rgb.data(), true) +
      upload_float_texture(textures.density.get(), map.width, map.height, 1, distribution.density.data()) +
      upload_float_texture(textures.marginal.get(), map.height + 1, 1, 1, distribution.marginal.data()) +
      upload_float_texture(textures.conditional.get(), map.width + 1, map.height, 1, distribution.conditional.data());
  gl::check_errors("upload_environment_textures");
  return textures;
}

bool KeptEnvironments::show(const std::string& key) {
  if (key.empty()) return false;
  const auto found = std::find_if(kept_.begin(), kept_.end(), [&](const Entry& entry) { return entry.key == key; });
  if (found == kept_.end()) return false;
  std::rotate(kept_.begin(), found, found + 1);
  return true;
}

void KeptEnvironments::add(std::string key, EnvironmentTextures textures) {
  // An environment without a key cannot be shown again: it goes once another is shown.
  std::erase_if(kept_, [&](const Entry& entry) { return entry.key.empty() || entry.key == key; });
  kept_.insert(kept_.begin(), Entry{std::move(key), std::move(textures)});
  std::size_t others = 0;
  for (std::size_t k = 1; k < kept_.size(); ++k) {
    others += kept_[k].textures.bytes;
    if (others > budget_bytes_) {
      kept_.resize(k);
      break;
    }
  }
}

}  // namespace skinlayer
