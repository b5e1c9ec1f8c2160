// The Python module `foveate`: the acuity model, displays, the planner, the
// papers' models, the image metrics on numpy arrays and the benchmark.
#include <pybind11/pybind11.h>

#include <string>

#include "convert.hpp"

#ifndef FOVEATE_PYTHON_EXECUTABLE
#define FOVEATE_PYTHON_EXECUTABLE "python3"
#endif

namespace {

namespace py = pybind11;

// The module is built for one interpreter (its Python version, with numpy):
// imported by another, it says which one it needs instead of failing later
// inside numpy.
void check_interpreter() {
  const py::module_ sys = py::module_::import("sys");
  const std::string here = py::str(sys.attr("executable"));
  const std::string built = FOVEATE_PYTHON_EXECUTABLE;
  const std::string version =
      std::to_string(PY_MAJOR_VERSION) + "." + std::to_string(PY_MINOR_VERSION);
  const std::string needs =
      "foveate: this module was built for " + built + " (Python " + version + ", with numpy)";
  const py::tuple v = sys.attr("version_info");
  if (v[0].cast<int>() != PY_MAJOR_VERSION || v[1].cast<int>() != PY_MINOR_VERSION) {
    throw py::import_error(needs + ", but " + here + " is Python " + std::string(py::str(v[0])) +
                           "." + std::string(py::str(v[1])) + ": run it with " + built +
                           ", or rebuild with -DPython_EXECUTABLE=" + here);
  }
  try {
    (void)py::module_::import("numpy");
  } catch (py::error_already_set& e) {
    throw py::import_error(needs + ", but numpy cannot be imported in " + here + " (" + e.what() +
                           "): run it with " + built +
                           ", install numpy for this interpreter, or rebuild with "
                           "-DPython_EXECUTABLE=" +
                           here);
  }
}

}  // namespace

PYBIND11_MODULE(foveate, m) {
  check_interpreter();
  foveate::python::bind_module(m);
}
