// A parallel-for for the tests (core takes one from its caller and starts no threads): the even indices on the
// calling thread, the odd ones on a second, so that the tests exercise concurrent use of a solve's shared state.
#pragma once

#include <functional>
#include <thread>

namespace skinlayer::test {

inline void two_threads(int count, const std::function<void(int)>& body) {
  std::thread other([&] {
    for (int i = 1; i < count; i += 2) body(i);
  });
  for (int i = 0; i < count; i += 2) body(i);
  other.join();
}

}  // namespace skinlayer::test
