#include "app/cli/error_report.h"

#include <exception>
#include <string>
#include <string_view>

#include "app/cli/errors.h"
#include "app/material/material_document.h"
#include "core/material.h"

namespace skinlayer::cli {
namespace {

int report(std::ostream& err, std::string_view message, int exit_status) {
  std::string line = "skinlayer: error: ";
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    line += (byte < 0x20 || byte == 0x7f) ? ' ' : c;
  }
  line += '\n';
  err << line;
  err.flush();
  return exit_status;
}

}  // namespace

int run_reporting_errors(std::ostream& err, const std::function<int()>& command) {
  try {
    return command();
  } catch (const ParameterError& error) {
    return report(err, error.what(), kExitUsage);
  } catch (const UsageError& error) {
    return report(err, error.what(), kExitUsage);
  } catch (const MaterialFileError& error) {
    return report(err, error.what(), kExitUsage);
  } catch (const InputError& error) {
    return report(err, error.what(), kExitFailure);
  } catch (const std::exception& error) {
    return report(err, error.what(), kExitFailure);
  } catch (...) {
    return report(err, "unexpected failure", kExitFailure);
  }
}

}  // namespace skinlayer::cli
