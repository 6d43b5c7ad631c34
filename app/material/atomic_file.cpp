#include "app/material/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace skinlayer {
namespace {

[[noreturn]] void fail(const std::string& path, int error) {
  throw std::runtime_error("cannot write " + path + ": " + std::strerror(error));
}

// Removes the temporary unless release() was called: no partial file survives an error.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!released_) ::unlink(path_.c_str());
  }
  int& descriptor() { return descriptor_; }
  const std::string& path() const { return path_; }
  void release() { released_ = true; }

 private:
  std::string path_;
  int descriptor_ = -1;
  bool released_ = false;
};

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
  if (path.empty()) throw std::runtime_error("cannot write a file with an empty name");
  // mkstemp's template: PATH.tmp-XXXXXX, in the target's folder so that the rename stays on one file system.
  std::vector<char> name(path.begin(), path.end());
  for (const char c : std::string_view(".tmp-XXXXXX")) name.push_back(c);
  name.push_back('\0');
  const int descriptor = ::mkstemp(name.data());
  if (descriptor < 0) fail(path, errno);
  TemporaryFile temporary(name.data());
  temporary.descriptor() = descriptor;
  // mkstemp creates 0600; a material or picture is an ordinary file (0666 less the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(descriptor, 0666 & ~mask) != 0) fail(path, errno);
  for (std::size_t written = 0; written < bytes.size();) {
    const ssize_t n = ::write(descriptor, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, errno);
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(descriptor) != 0) fail(path, errno);
  const int closed = ::close(descriptor);
  temporary.descriptor() = -1;
  if (closed != 0) fail(path, errno);
  if (::rename(temporary.path().c_str(), path.c_str()) != 0) fail(path, errno);
  temporary.release();
}

}  // namespace skinlayer
