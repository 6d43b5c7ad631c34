// The figures' text face: DejaVu Sans through stb_truetype (libstb-dev), or, when the font file is missing, the
// built-in stb_easy_font bitmap face (ASCII only; Greek letters and symbols are spelt out) so labels still appear.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace skinlayer::figures {

// A coverage mask of rendered text: width x height bytes, 0 (empty) to 255 (covered), top row first. The text's
// baseline lies `baseline` pixels below the top row.
struct TextMask {
  int width = 0;
  int height = 0;
  int baseline = 0;
  std::vector<std::uint8_t> coverage;
};

class Font {
 public:
  // Loads the first TrueType file found among the usual DejaVu Sans paths; falls back to stb_easy_font.
  Font();
  // The same with the candidate TrueType files given (none readable: the fallback face).
  explicit Font(const std::vector<std::string>& candidate_paths);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  bool is_truetype() const;

  // Renders UTF-8 text with the given pixel height (ascent to descent).
  TextMask render(std::string_view utf8, double pixel_height) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skinlayer::figures
