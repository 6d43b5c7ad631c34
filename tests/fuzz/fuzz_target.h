// What every fuzz target here shares (tests/fuzz/CMakeLists.txt builds each with libFuzzer under SKINLAYER_FUZZ, or
// with replay_corpus.cpp, which feeds it its corpus, otherwise).
//
// A target hands the bytes to one reader of untrusted input. The reader may refuse them only with the error types
// it documents, and every refusal must be one clear line: not empty, no line breaks or other control characters
// (the user sees it on a terminal). Anything else, a crash, a sanitizer report, another exception or a broken
// property, stops the process through fuzz_failure(), which libFuzzer keeps as a crash input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace skinlayer::fuzz {

[[noreturn]] inline void fuzz_failure(std::string_view what) {
  std::fprintf(stderr, "fuzz target failed: %.*s\n", static_cast<int>(what.size()), what.data());
  std::abort();
}

inline void require(bool holds, std::string_view what) {
  if (!holds) fuzz_failure(what);
}

inline std::string_view input_bytes(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// An error message fit for a terminal: one line, not empty, no control character.
inline void require_one_line(std::string_view message) {
  require(!message.empty(), "an empty error message");
  for (std::size_t n = 0; n < message.size(); ++n) {
    const auto byte = static_cast<unsigned char>(message[n]);
    if (byte < 0x20 || byte == 0x7f) {
      fuzz_failure("control character " + std::to_string(byte) + " at byte " + std::to_string(n) +
                   " of the error message: " + std::string(message.substr(0, n)));
    }
  }
}

// Runs read(); a thrown Expected... must be one line (above), any other exception escapes to libFuzzer (a crash).
template <class... Expected, class Read>
bool refused_cleanly(Read&& read) {
  try {
    read();
    return false;
  } catch (const std::exception& error) {
    if (!(dynamic_cast<const Expected*>(&error) || ...)) {
      fuzz_failure(std::string("an undocumented exception: ") + error.what());
    }
    require_one_line(error.what());
    return true;
  }
}

}  // namespace skinlayer::fuzz
