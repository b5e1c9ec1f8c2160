// The Python module `foveate`: the acuity model, displays, the planner, the
// papers' models, the image metrics on numpy arrays and the benchmark.
#include <pybind11/pybind11.h>

#include "convert.hpp"

PYBIND11_MODULE(foveate, m) { foveate::python::bind_module(m); }
