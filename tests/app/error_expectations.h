// The command line's error contract as a GoogleTest predicate.
#pragma once

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

#include "tests/app/process_runner.h"

namespace skinlayer::test {

// Succeeds when the process exited with exit_code, wrote nothing to stdout, and wrote exactly one line to stderr,
// starting "skinlayer: error: " and containing every fragment.
::testing::AssertionResult failed_with_one_line(const ProcessResult& result, int exit_code,
                                                const std::vector<std::string_view>& fragments);

}  // namespace skinlayer::test
