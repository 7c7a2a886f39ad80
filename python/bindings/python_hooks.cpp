#include "python_hooks.hpp"

namespace cvtmesh::python {

PythonHooks::PythonHooks() {
  const py::module_ threading = py::module_::import("threading");
  caller_handles_signals_ = threading.attr("current_thread")().is(threading.attr("main_thread")());
}

bool PythonHooks::cancel_requested() {
  if (stopped_) return true;
  // Signal handlers only run on Python's main thread, with the GIL. Only that thread, when it
  // is the one that called in (and released the GIL), checks: worker threads, and a call made
  // from another Python thread (a Dask worker's task), never wait for the GIL here.
  if (!caller_handles_signals_ || std::this_thread::get_id() != caller_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_check_ < std::chrono::milliseconds(50)) return false;
  last_check_ = now;
  with_gil([] {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  });
  return stopped_;
}

void PythonHooks::keep(py::error_already_set&& e) {
  error_.emplace(std::move(e));
  stopped_ = true;
}

void PythonHooks::raise_if_stopped() {
  if (error_) {
    py::error_already_set e = std::move(*error_);
    error_.reset();
    throw e;
  }
}

}  // namespace cvtmesh::python
