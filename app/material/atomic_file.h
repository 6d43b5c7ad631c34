// Writing a file so that it is either whole or absent: the bytes go to a temporary file in the same folder, are
// flushed to disk, and the temporary is renamed over the target (rename(2) is atomic within a file system).
#pragma once

#include <string>
#include <string_view>

namespace skinlayer {

// Throws std::runtime_error "cannot write PATH: reason" (an unwritable folder, a full disk, ...); the temporary
// file is removed then, and the target is left as it was.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace skinlayer
