#include "tests/app/process_runner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace skinlayer::test {
namespace {

// A file in the temporary folder, open for reading and writing, removed on destruction.
class TempFile {
 public:
  TempFile() : path_((std::filesystem::temp_directory_path() / "skinlayer-app-test-XXXXXX").string()) {
    fd_ = ::mkstemp(path_.data());
    if (fd_ < 0) throw std::runtime_error("mkstemp failed: " + std::string(std::strerror(errno)));
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    ::close(fd_);
    ::unlink(path_.c_str());
  }

  int fd() const { return fd_; }

  void write_and_rewind(std::string_view text) const {
    while (!text.empty()) {
      const ssize_t written = ::write(fd_, text.data(), text.size());
      if (written < 0 && errno == EINTR) continue;
      if (written < 0) throw std::runtime_error("write failed: " + std::string(std::strerror(errno)));
      text.remove_prefix(static_cast<std::size_t>(written));
    }
    if (::lseek(fd_, 0, SEEK_SET) != 0) throw std::runtime_error("lseek failed");
  }

  std::string read_all() const {
    std::ifstream in(path_, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

 private:
  std::string path_;
  int fd_ = -1;
};

// posix_spawn file actions, destroyed on scope exit.
class SpawnFileActions {
 public:
  SpawnFileActions() { ::posix_spawn_file_actions_init(&actions_); }
  SpawnFileActions(const SpawnFileActions&) = delete;
  SpawnFileActions& operator=(const SpawnFileActions&) = delete;
  ~SpawnFileActions() { ::posix_spawn_file_actions_destroy(&actions_); }

  void redirect(int from_fd, int to_fd) { ::posix_spawn_file_actions_adddup2(&actions_, from_fd, to_fd); }
  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_{};
};

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, std::string_view stdin_text) {
  if (argv.empty()) throw std::invalid_argument("run_process: no program");
  const TempFile in;
  const TempFile out;
  const TempFile err;
  in.write_and_rewind(stdin_text);

  SpawnFileActions actions;
  actions.redirect(in.fd(), STDIN_FILENO);
  actions.redirect(out.fd(), STDOUT_FILENO);
  actions.redirect(err.fd(), STDERR_FILENO);

  std::vector<std::string> storage = argv;
  std::vector<char*> pointers;
  for (std::string& argument : storage) pointers.push_back(argument.data());
  pointers.push_back(nullptr);

  pid_t pid = 0;
  const int spawn_error = ::posix_spawnp(&pid, storage.front().c_str(), actions.get(), nullptr, pointers.data(), environ);
  if (spawn_error != 0) {
    throw std::runtime_error("cannot start " + storage.front() + ": " + std::strerror(spawn_error));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed: " + std::string(std::strerror(errno)));
  }
  ProcessResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  result.out = out.read_all();
  result.err = err.read_all();
  return result;
}

std::optional<std::string> find_in_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::string_view rest = path;
  while (!rest.empty()) {
    const std::size_t colon = rest.find(':');
    const std::string_view folder = rest.substr(0, colon);
    rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
    if (folder.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(folder) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return std::nullopt;
}

std::vector<std::string> command_names_in(std::string_view error) {
  constexpr std::string_view kMarker = "the commands are ";
  const std::size_t at = error.find(kMarker);
  if (at == std::string_view::npos) return {};
  std::string_view list = error.substr(at + kMarker.size());
  list = list.substr(0, list.find('\n'));
  std::vector<std::string> names;
  std::istringstream words{std::string(list)};
  for (std::string name; words >> name;) {
    if (name == "and") continue;
    if (name.back() == ',') name.pop_back();
    names.push_back(name);
  }
  return names;
}

}  // namespace skinlayer::test
