#include "tests/app/process_runner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
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

ProcessResult run_skinlayer(const std::vector<std::string>& arguments, std::string_view stdin_text) {
  const TempFile in;
  const TempFile out;
  const TempFile err;
  in.write_and_rewind(stdin_text);

  SpawnFileActions actions;
  actions.redirect(in.fd(), STDIN_FILENO);
  actions.redirect(out.fd(), STDOUT_FILENO);
  actions.redirect(err.fd(), STDERR_FILENO);

  std::string executable = SKINLAYER_EXECUTABLE;
  std::vector<std::string> argument_storage = arguments;
  std::vector<char*> argv = {executable.data()};
  for (std::string& argument : argument_storage) argv.push_back(argument.data());
  argv.push_back(nullptr);

  pid_t pid = 0;
  const int spawn_error = ::posix_spawn(&pid, executable.c_str(), actions.get(), nullptr, argv.data(), environ);
  if (spawn_error != 0) {
    throw std::runtime_error("cannot start " + executable + ": " + std::strerror(spawn_error));
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

}  // namespace skinlayer::test
