#include "app/cli/figures_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/figures/figure_builder.h"
#include "app/figures/figure_index.h"
#include "app/figures/figure_set.h"
#include "app/figures/font.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {
namespace {

// "lobe-g, lobe-sigma, ...": every figure's name, in the set's order.
std::string figure_names() {
  std::string names;
  for (const figures::FigureSpec& spec : figures::figure_set()) names += (names.empty() ? "" : ", ") + spec.name;
  return names;
}

// The same, wrapped in lines of up to 110 columns indented under the flags' descriptions.
std::string wrapped_figure_names() {
  const std::string indent(21, ' ');
  std::string text = indent;
  std::size_t column = indent.size();
  const std::vector<figures::FigureSpec> set = figures::figure_set();
  for (std::size_t k = 0; k < set.size(); ++k) {
    const std::string word = set[k].name + (k + 1 < set.size() ? "," : "");
    if (column + 1 + word.size() > 110 && column > indent.size()) {
      text += "\n" + indent;
      column = indent.size();
    } else if (column > indent.size()) {
      text += ' ';
      ++column;
    }
    text += word;
    column += word.size();
  }
  return text;
}

// The figures --only names, in the set's order; the whole set without it. An unknown name is a UsageError that
// lists them.
std::vector<figures::FigureSpec> chosen_figures(const ParsedFlags& flags) {
  std::vector<figures::FigureSpec> set = figures::figure_set();
  const std::optional<std::string_view> only = flags.value("only");
  if (!only) return set;
  std::vector<std::string_view> names = split_list(*only, ',');
  for (const std::string_view name : names) {
    const bool known =
        std::any_of(set.begin(), set.end(), [&](const figures::FigureSpec& s) { return s.name == name; });
    if (!known) {
      throw UsageError("only = " + text::quoted(name) + " is not a figure; the figures are " + figure_names());
    }
  }
  std::erase_if(set, [&](const figures::FigureSpec& spec) {
    return std::find(names.begin(), names.end(), spec.name) == names.end();
  });
  return set;
}

}  // namespace

std::string figures_usage() {
  return "Usage: skinlayer figures -o DIR [--size PX] [--only NAME[,NAME...]]\n"
         "\n"
         "Regenerates the results figures: for each, DIR/NAME.png (polar lobe plots with axis labels, legend and\n"
         "parameter values, or the Lambert | Hanrahan-Krueger | Stam spheres) and DIR/NAME.csv (the data behind\n"
         "it, with the material flags that skinlayer eval reproduces it with), and DIR/index.html showing them all.\n"
         "η is 1.4 and the incident angle 45° unless a figure varies them.\n"
         "  -o, --output DIR   the folder to write (created if missing; required)\n"
         "  --size PX          side of the square plots in pixels, a whole number in [160, 4096] (default 640)\n"
         "  --only NAMES       only these figures, comma-separated (index.html then shows them alone), of:\n" +
         wrapped_figure_names() + "\n";
}

int run_figures_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const std::vector<std::string_view> known = {"output", "size", "only"};
  const ParsedFlags flags = ParsedFlags::parse(arguments, known, "skinlayer figures");
  const std::optional<std::string_view> output = flags.value("output");
  if (!output) throw UsageError("figures needs -o DIR (the folder to write)");
  int size = 640;
  if (const std::optional<std::string_view> text = flags.value("size")) {
    const std::optional<double> value = text::parse_number(*text);
    if (!value || *value != static_cast<int>(*value) || *value < 160 || *value > 4096) {
      throw UsageError("size = " + text::quoted(*text) + " must be a whole number of pixels in [160, 4096]");
    }
    size = static_cast<int>(*value);
  }
  const std::vector<figures::FigureSpec> set = chosen_figures(flags);  // before the folder is made
  const std::filesystem::path dir{std::string(*output)};
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    throw std::runtime_error("cannot create the folder " + dir.string() + ": " +
                             (error ? error.message() : std::string("a file of that name exists")));
  }

  const figures::Font font;
  if (!font.is_truetype()) out << "note: DejaVu Sans not found; labels use the built-in bitmap face\n";
  figures::SolveCache cache;
  std::vector<figures::FigureSize> sizes;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < set.size(); ++k) {
    const auto begin = std::chrono::steady_clock::now();
    sizes.push_back(figures::build_figure(set[k], dir, font, cache, size));
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - begin;
    char line[160];
    std::snprintf(line, sizeof line, "[%zu/%zu] %s ... %.2f s\n", k + 1, set.size(), set[k].name.c_str(),
                  seconds.count());
    out << line << std::flush;
  }
  figures::write_figure_index(set, sizes, dir);
  const std::chrono::duration<double> total = std::chrono::steady_clock::now() - start;
  char line[160];
  std::snprintf(line, sizeof line, "wrote %zu figures and index.html to %s in %.1f s\n", set.size(),
                dir.string().c_str(), total.count());
  out << line;
  return kExitSuccess;
}

}  // namespace skinlayer::cli
