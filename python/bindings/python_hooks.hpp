// What lets a long library call run with the GIL released and still answer to Python: Ctrl-C
// (KeyboardInterrupt) and exceptions raised in a Python progress callback stop the work
// (through RemeshSettings::cancel) and are raised again in the caller.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

namespace cvtmesh::python {

namespace py = pybind11;

class PythonHooks {
 public:
  PythonHooks();  // with the GIL
  // For RemeshSettings::cancel: thread-safe and cheap; when called in from Python's main
  // thread, on that thread and at most every 50 ms, takes the GIL to let Python look at pending
  // signals.
  bool cancel_requested();
  // Runs `call` with the GIL; a Python exception it raises is kept and stops the work.
  template <class F>
  void with_gil(F&& call) {
    if (stopped_) return;
    py::gil_scoped_acquire gil;
    try {
      call();
    } catch (py::error_already_set& e) {
      keep(std::move(e));
    }
  }
  // Raises what stopped the work, if anything did (called with the GIL).
  void raise_if_stopped();

 private:
  void keep(py::error_already_set&& e);

  std::atomic<bool> stopped_{false};
  std::optional<py::error_already_set> error_;
  const std::thread::id caller_ = std::this_thread::get_id();
  bool caller_handles_signals_ = false;
  std::chrono::steady_clock::time_point last_check_ = std::chrono::steady_clock::now();
};

}  // namespace cvtmesh::python
