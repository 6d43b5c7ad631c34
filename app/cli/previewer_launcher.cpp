#include "app/cli/previewer_launcher.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace skinlayer::cli {
namespace {

constexpr std::string_view kWindowExecutable = "skinlayer-window";

std::filesystem::path window_executable() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw std::runtime_error("cannot locate the skinlayer executable (/proc/self/exe: " + error.message() + ")");
  return self.parent_path() / kWindowExecutable;
}

}  // namespace

bool is_previewer_invocation(std::span<const std::string_view> arguments) {
  if (arguments.empty()) return true;
  const std::string_view first = arguments.front();
  return first.starts_with("--") && first != "--help" && first != "--version";
}

void exec_previewer(int argc, char** argv) {
  const std::filesystem::path window = window_executable();
  std::error_code error;
  if (!std::filesystem::exists(window, error)) {
    throw std::runtime_error("the previewer " + window.string() +
                             " is missing (build the skinlayer-window target); render headless with: skinlayer "
                             "render -o out.png");
  }
  std::string program = window.string();
  std::vector<char*> arguments = {program.data()};
  for (int k = 1; k < argc; ++k) arguments.push_back(argv[k]);
  arguments.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  ::execv(program.c_str(), arguments.data());
  throw std::runtime_error("cannot start the previewer " + program + ": " + std::strerror(errno));
}

}  // namespace skinlayer::cli
