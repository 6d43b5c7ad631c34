// skinlayer figures -o DIR [--size PX]: regenerates the results figures (PNG + CSV each, and index.html).
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string figures_usage();

// Writes every figure of figures::figure_set() into the folder (created if missing), one progress line per figure
// on out. Throws UsageError for a bad command line and std::runtime_error if a file cannot be written.
int run_figures_command(std::span<const std::string_view> arguments, std::ostream& out);

}  // namespace skinlayer::cli
