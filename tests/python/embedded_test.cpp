// The Python module, run in an embedded interpreter beside a technique
// registered in C++ from outside the library (examples/bench_consumer): with
// no change of its own the module lists it and measures it by default.
#include <gtest/gtest.h>
#include <pybind11/embed.h>

#include <algorithm>
#include <string>
#include <vector>

#include "convert.hpp"
#include "native_copy.hpp"

PYBIND11_EMBEDDED_MODULE(foveate, m) { foveate::python::bind_module(m); }

namespace py = pybind11;
using namespace py::literals;

TEST(PythonModule, ListsAndMeasuresATechniqueRegisteredFromOutside) {
  example::register_native_copy();
  const py::scoped_interpreter python;
  const py::module_ fv = py::module_::import("foveate");
  std::vector<std::string> listed;
  for (py::handle t : fv.attr("techniques")()) listed.push_back(t["name"].cast<std::string>());
  EXPECT_NE(std::find(listed.begin(), listed.end(), example::kNativeCopy), listed.end());
  const py::dict r = fv.attr("bench")("scene"_a = "cheap", "size"_a = py::make_tuple(48, 27),
                                      "frames"_a = 1, "warmup"_a = 0, "metrics"_a = false);
  std::vector<std::string> measured;
  for (py::handle x : r["results"]) measured.push_back(x["technique"].cast<std::string>());
  EXPECT_NE(std::find(measured.begin(), measured.end(), example::kNativeCopy), measured.end());
  EXPECT_NE(std::find(measured.begin(), measured.end(), "vrs"), measured.end());
}
