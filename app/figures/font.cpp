#include "app/figures/font.h"

#include <stb_easy_font.h>  // header-only (static functions)
#include <stb_truetype.h>   // libstb.so holds the implementation: do not define STB_TRUETYPE_IMPLEMENTATION

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

namespace skinlayer::figures {
namespace {

// Where Debian (fonts-dejavu-core) and other distributions put DejaVu Sans.
const std::vector<std::string>& default_font_paths() {
  static const std::vector<std::string> paths = {
      "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
      "/usr/share/fonts/dejavu/DejaVuSans.ttf",
      "/usr/share/fonts/TTF/DejaVuSans.ttf",
  };
  return paths;
}

// Decodes one UTF-8 code point at text[k] and advances k; malformed bytes decode as '?'.
char32_t next_code_point(std::string_view text, std::size_t& k) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(k);
  int extra = 0;
  char32_t value = lead;
  if (lead >= 0xF0) {
    extra = 3;
    value = lead & 0x07u;
  } else if (lead >= 0xE0) {
    extra = 2;
    value = lead & 0x0Fu;
  } else if (lead >= 0xC0) {
    extra = 1;
    value = lead & 0x1Fu;
  } else if (lead >= 0x80) {
    ++k;
    return U'?';
  }
  ++k;
  for (int i = 0; i < extra; ++i, ++k) {
    if (k >= text.size() || (byte(k) & 0xC0u) != 0x80u) return U'?';
    value = (value << 6) | (byte(k) & 0x3Fu);
  }
  return value;
}

// ASCII spelling of the symbols the figures use, for the bitmap fallback face.
std::string ascii_spelling(std::string_view utf8) {
  std::string out;
  for (std::size_t k = 0; k < utf8.size();) {
    const char32_t c = next_code_point(utf8, k);
    switch (c) {
      case U'σ': out += "sigma"; break;
      case U'η': out += "eta"; break;
      case U'Ω': out += "Omega"; break;
      case U'θ': out += "theta"; break;
      case U'τ': out += "tau"; break;
      case U'°': out += " deg"; break;
      case U'–': case U'—': out += '-'; break;
      case U'·': out += '*'; break;
      default: out += c < 128 ? static_cast<char>(c) : '?';
    }
  }
  return out;
}

}  // namespace

struct Font::Impl {
  std::vector<unsigned char> data;  // the TrueType file; info points into it
  stbtt_fontinfo info{};
  bool truetype = false;
};

Font::Font() : Font(default_font_paths()) {}

Font::Font(const std::vector<std::string>& candidate_paths) : impl_(std::make_unique<Impl>()) {
  for (const std::string& path : candidate_paths) {
    std::ifstream file(path, std::ios::binary);
    if (!file) continue;
    impl_->data.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    if (!impl_->data.empty() &&
        stbtt_InitFont(&impl_->info, impl_->data.data(), stbtt_GetFontOffsetForIndex(impl_->data.data(), 0)) != 0) {
      impl_->truetype = true;
      return;
    }
  }
  impl_->data.clear();
}

Font::~Font() = default;

bool Font::is_truetype() const { return impl_->truetype; }

TextMask Font::render(std::string_view utf8, double pixel_height) const {
  TextMask mask;
  if (impl_->truetype) {
    const stbtt_fontinfo& info = impl_->info;
    const float scale = stbtt_ScaleForPixelHeight(&info, static_cast<float>(pixel_height));
    int ascent = 0, descent = 0, line_gap = 0;
    stbtt_GetFontVMetrics(&info, &ascent, &descent, &line_gap);
    mask.baseline = static_cast<int>(std::ceil(static_cast<float>(ascent) * scale));
    mask.height = mask.baseline + static_cast<int>(std::ceil(static_cast<float>(-descent) * scale)) + 1;
    // Pass 1: code points and pen positions (with kerning); pass 2: rasterize into the mask.
    std::vector<std::pair<int, float>> glyphs;  // glyph index, pen x
    float pen = 1.0f;
    int previous = 0;
    for (std::size_t k = 0; k < utf8.size();) {
      const int glyph = stbtt_FindGlyphIndex(&info, static_cast<int>(next_code_point(utf8, k)));
      if (previous != 0) pen += scale * static_cast<float>(stbtt_GetGlyphKernAdvance(&info, previous, glyph));
      glyphs.emplace_back(glyph, pen);
      int advance = 0, left_bearing = 0;
      stbtt_GetGlyphHMetrics(&info, glyph, &advance, &left_bearing);
      pen += scale * static_cast<float>(advance);
      previous = glyph;
    }
    mask.width = static_cast<int>(std::ceil(pen)) + 2;
    mask.coverage.assign(static_cast<std::size_t>(mask.width) * mask.height, 0);
    std::vector<unsigned char> glyph_pixels;
    for (const auto& [glyph, x] : glyphs) {
      int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
      const float shift = x - std::floor(x);
      stbtt_GetGlyphBitmapBoxSubpixel(&info, glyph, scale, scale, shift, 0.0f, &x0, &y0, &x1, &y1);
      const int w = x1 - x0, h = y1 - y0;
      if (w <= 0 || h <= 0) continue;
      glyph_pixels.assign(static_cast<std::size_t>(w) * h, 0);
      stbtt_MakeGlyphBitmapSubpixel(&info, glyph_pixels.data(), w, h, w, scale, scale, shift, 0.0f, glyph);
      const int left = static_cast<int>(std::floor(x)) + x0;
      const int top = mask.baseline + y0;
      for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w; ++col) {
          const int mx = left + col, my = top + row;
          if (mx < 0 || my < 0 || mx >= mask.width || my >= mask.height) continue;
          std::uint8_t& cell = mask.coverage[static_cast<std::size_t>(my) * mask.width + mx];
          cell = std::max(cell, glyph_pixels[static_cast<std::size_t>(row) * w + col]);
        }
      }
    }
    return mask;
  }
  // Fallback: stb_easy_font's quads (a 7-pixel-high face), scaled by a whole factor.
  std::string text = ascii_spelling(utf8);
  const int factor = std::max(1, static_cast<int>(std::lround(pixel_height / 9.0)));
  std::vector<char> vertices((text.size() + 1) * 1024);  // at most a few 64-byte quads per character
  const int quads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, vertices.data(),
                                        static_cast<int>(vertices.size()));
  mask.width = (stb_easy_font_width(text.data()) + 2) * factor;
  mask.height = 10 * factor;
  mask.baseline = 7 * factor;
  mask.coverage.assign(static_cast<std::size_t>(mask.width) * mask.height, 0);
  constexpr std::size_t kVertexBytes = 16;  // x, y, z as float, then 4 color bytes
  for (int q = 0; q < quads; ++q) {
    float corner[2][2] = {};
    for (int v = 0; v < 4; v += 2) {  // vertices 0 and 2 are opposite corners
      const char* vertex = vertices.data() + (static_cast<std::size_t>(q) * 4 + static_cast<std::size_t>(v)) * kVertexBytes;
      std::copy_n(vertex, sizeof(float), reinterpret_cast<char*>(&corner[v / 2][0]));
      std::copy_n(vertex + sizeof(float), sizeof(float), reinterpret_cast<char*>(&corner[v / 2][1]));
    }
    for (int y = static_cast<int>(corner[0][1]) * factor; y < static_cast<int>(corner[1][1]) * factor; ++y) {
      for (int x = static_cast<int>(corner[0][0]) * factor; x < static_cast<int>(corner[1][0]) * factor; ++x) {
        if (x >= 0 && y >= 0 && x < mask.width && y < mask.height) {
          mask.coverage[static_cast<std::size_t>(y) * mask.width + x] = 255;
        }
      }
    }
  }
  return mask;
}

}  // namespace skinlayer::figures
