// What `skinlayer validate` prints and writes: per set, a table of each quantity's Monte Carlo estimate, its
// standard error, the solver's value and their difference in standard errors and relative terms; a summary of all
// sets; and a Markdown report (validation.md) with one PNG per set (validation_plot.h) beside it.
#pragma once

#include <filesystem>
#include <ostream>
#include <span>
#include <string>

#include "app/validate/validation_run.h"

namespace skinlayer::validation {

struct RunDescription {
  std::string mode;  // "quick" or "full"
  std::uint64_t seed = 1;
  int threads = 1;
  double seconds = 0.0;
};

// The albedo rows and the judged bins that come worst, then one verdict line.
void print_set_table(std::ostream& out, const SetResult& result);

// One row per set: the albedo differences in standard errors, the worst judged comparison, the verdict.
void print_summary(std::ostream& out, std::span<const SetResult> results);

// Writes dir/validation.md (every comparison of every set, linking dir/<set>.png, which the caller writes).
// Throws std::runtime_error if it cannot be written.
void write_markdown_report(const std::filesystem::path& dir, std::span<const SetResult> results,
                           const RunDescription& run);

}  // namespace skinlayer::validation
