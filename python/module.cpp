// The Python module `foveate`: the acuity model, displays, the planner, the
// papers' models, the image metrics on numpy arrays and the benchmark.
#include <pybind11/pybind11.h>

#include "convert.hpp"
#include "foveate/core/error.hpp"

PYBIND11_MODULE(foveate, m) {
  m.doc() =
      "foveate: foveated rendering driven by one acuity model (w(e) = m e + w0), measured "
      "against native rendering";
  m.attr("__version__") = FOVEATE_VERSION;
  // Bad input (a file, a value, a key) raises foveate.Error, a ValueError.
  pybind11::register_exception<foveate::Error>(m, "Error", PyExc_ValueError);
  foveate::python::bind_core(m);
  foveate::python::bind_metrics(m);
  foveate::python::bind_bench(m);
}
