// Everything the module `foveate` holds, bound into `m` (module.cpp for the
// extension, the embedded interpreter of the tests).
#include "convert.hpp"
#include "foveate/core/error.hpp"

namespace foveate::python {

void bind_module(py::module_& m) {
  m.doc() =
      "foveate: foveated rendering driven by one acuity model (w(e) = m e + w0), measured "
      "against native rendering";
  m.attr("__version__") = FOVEATE_VERSION;
  // Bad input (a file, a value, a key) raises foveate.Error, a ValueError.
  py::register_exception<Error>(m, "Error", PyExc_ValueError);
  bind_core(m);
  bind_metrics(m);
  bind_bench(m);
}

}  // namespace foveate::python
