// Library errors as Python exceptions, with the library's one-line message.
#include "cvtmesh/errors.hpp"
#include "bindings.hpp"

namespace cvtmesh::python {

void add_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const FileError& e) {  // missing, a directory, cannot be opened
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const InputError& e) {  // the caller's data: a bad mesh or file content
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const InvalidArgument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const OutputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const ResourceError& e) {
      PyErr_SetString(PyExc_MemoryError, e.what());
    } catch (const Cancelled& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
}

}  // namespace cvtmesh::python
