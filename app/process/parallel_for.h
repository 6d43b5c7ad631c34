// The parallel-for the executables hand to core (SolveOptions::parallel_for): core starts no threads itself.
#pragma once

#include <functional>

namespace skinlayer {

// Runs body(0) ... body(count - 1) on up to std::thread::hardware_concurrency() threads (the calling thread is one
// of them), each index once, and returns when all are done. The first exception a body throws is rethrown here,
// after every thread has finished.
void parallel_for_threads(int count, const std::function<void(int)>& body);

}  // namespace skinlayer
