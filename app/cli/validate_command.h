// skinlayer validate [--quick] [-o DIR] [--set NAMES] [--seed N] [--threads N]: the solver against the independent
// Monte Carlo reference over the validation grid (app/validate/), with a table per set, a summary, and a Markdown
// report with one plot per set.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string validate_usage();

// Runs the sets, printing progress (the set and the paths traced so far) and the tables on out, and writes
// DIR/validation.md and DIR/<set>.png. Returns kExitSuccess when every set agrees and kExitFailure when any set
// disagrees. Throws UsageError for a bad command line and std::runtime_error if a file cannot be written.
int run_validate_command(std::span<const std::string_view> arguments, std::ostream& out);

}  // namespace skinlayer::cli
