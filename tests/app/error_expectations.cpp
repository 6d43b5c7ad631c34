#include "tests/app/error_expectations.h"

#include <string>

namespace skinlayer::test {

::testing::AssertionResult failed_with_one_line(const ProcessResult& result, int exit_code,
                                                const std::vector<std::string_view>& fragments) {
  const std::string context = "\n  exit code: " + std::to_string(result.exit_code) + "\n  stdout: [" + result.out +
                              "]\n  stderr: [" + result.err + "]";
  if (result.exit_code != exit_code) {
    return ::testing::AssertionFailure() << "expected exit code " << exit_code << context;
  }
  if (!result.out.empty()) return ::testing::AssertionFailure() << "expected no output on stdout" << context;
  const std::string_view err = result.err;
  if (!err.starts_with("skinlayer: error: ") || !err.ends_with('\n') || err.find('\n') != err.size() - 1) {
    return ::testing::AssertionFailure() << "expected one line 'skinlayer: error: ...' on stderr" << context;
  }
  for (const std::string_view fragment : fragments) {
    if (err.find(fragment) == std::string_view::npos) {
      return ::testing::AssertionFailure() << "expected stderr to contain '" << fragment << "'" << context;
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace skinlayer::test
