// Long C++ work called from Python: run on a thread of its own with the GIL released, so that other Python threads
// keep running, while the calling thread wakes every 50 ms to let Python handle signals. Ctrl-C (or any handler that
// raises) asks the work to stop through its `cancelled` callback, waits for it, and raises the Python exception.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <future>

namespace skinlayer::python {

// work(cancelled) -> R, where cancelled() turns true once a signal handler raised. Exceptions that the work throws
// are rethrown here (pybind11 translates them); a raised signal handler's exception wins over them.
template <class Work>
auto run_interruptible(Work&& work) {
  namespace py = pybind11;
  std::atomic<bool> interrupted = false;
  const std::function<bool()> cancelled = [&interrupted] { return interrupted.load(); };
  auto result = std::async(std::launch::async, [&work, &cancelled] { return work(cancelled); });
  bool raised = false;
  {
    const py::gil_scoped_release release;
    while (result.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      const py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        raised = true;
        interrupted = true;
        break;
      }
    }
    result.wait();
  }
  if (raised) throw py::error_already_set();
  return result.get();
}

}  // namespace skinlayer::python
