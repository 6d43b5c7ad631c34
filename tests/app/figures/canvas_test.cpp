// The figures' raster: text through DejaVu Sans or, without the font file, the stb_easy_font fallback (both must
// put ink on the canvas, Greek included); anti-aliased lines and filled circles land where they are drawn.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "app/figures/canvas.h"
#include "app/figures/font.h"

namespace skinlayer::figures {
namespace {

constexpr Rgba kWhite{255, 255, 255, 255};
constexpr Rgba kBlack{0, 0, 0, 255};

// Pixels of the canvas darker than white.
int inked_pixels(const Canvas& canvas) {
  int count = 0;
  const std::vector<std::uint8_t>& rgba = canvas.image().rgba;
  for (std::size_t k = 0; k < rgba.size(); k += 4) count += rgba[k] < 250 ? 1 : 0;
  return count;
}

std::uint8_t red_at(const Canvas& canvas, int x, int y) {
  return canvas.image().rgba[(static_cast<std::size_t>(y) * canvas.width() + x) * 4];
}

TEST(FigureFont, FallbackFaceWritesTextWithoutTheFontFile) {
  const Font font(std::vector<std::string>{"/nonexistent/font.ttf"});
  EXPECT_FALSE(font.is_truetype());
  const TextMask mask = font.render("σ = 0.5", 18.0);  // spelt "sigma = 0.5"
  EXPECT_GT(mask.width, 40);
  Canvas canvas(200, 40, kWhite);
  EXPECT_GT(canvas.text(font, "σ = 0.5, θi 45°", {4, 28}, 18.0, kBlack), 40.0);
  EXPECT_GT(inked_pixels(canvas), 50);
}

TEST(FigureFont, TrueTypeFaceRendersGreek) {
  const Font font;
  if (!font.is_truetype()) GTEST_SKIP() << "DejaVu Sans is not installed (fonts-dejavu-core)";
  Canvas canvas(200, 40, kWhite);
  const double width = canvas.text(font, "σηΩθ", {4, 28}, 20.0, kBlack);
  EXPECT_GT(width, 30.0);
  EXPECT_GT(inked_pixels(canvas), 50);
}

TEST(FigureCanvas, LinesAndCirclesLandWhereDrawn) {
  Canvas canvas(64, 64, kWhite);
  canvas.line({8, 32}, {56, 32}, kBlack, 2.0);
  EXPECT_LT(red_at(canvas, 32, 31), 10);  // on the line (pixel centres at y 31.5 and 32.5)
  EXPECT_EQ(red_at(canvas, 32, 20), 255);  // well off it
  canvas.fill_circle({16, 12}, 5.0, kBlack);
  EXPECT_LT(red_at(canvas, 16, 12), 10);
  EXPECT_EQ(red_at(canvas, 16, 24), 255);
}

}  // namespace
}  // namespace skinlayer::figures
