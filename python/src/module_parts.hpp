#pragma once
// What the module's files share: the parts Python names (the built-ins, eval's oracles and what
// Python registers), numpy views of the core's spans, and the binders each file defines.

#include <span>

#include <Eigen/Core>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "anchorbench/registry/components.hpp"

namespace anchorbench::python {

namespace py = pybind11;
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Ints = py::array_t<int, py::array::c_style | py::array::forcecast>;

// Made at import, never destroyed (it holds Python callables registered as parts, which must not
// be released after the interpreter is gone).
registry::Components& ModuleComponents();

// An (N, 3) array of positions as the core's span, without a copy; throws ValueError naming `what`.
std::span<const Eigen::Vector3d> Points(const Doubles& array, const char* what);
// An (N,) array as a span, without a copy; `n` (if >= 0) is the length it must have.
std::span<const double> Values(const Doubles& array, const char* what, py::ssize_t n = -1);
std::span<const int> IntValues(const Ints& array, const char* what, py::ssize_t n = -1);
// Read-only numpy views of the core's spans, valid only while the call that hands them out runs.
py::array View(std::span<const Eigen::Vector3d> points);
py::array View(std::span<const double> values);
// Copies, for results that outlive the call.
py::array Copy(const Eigen::Vector3d& v);
py::array Copy(const Eigen::Matrix4d& m);

void BindCore(py::module_& m);
void BindTrials(py::module_& m);
void BindPlugins(py::module_& m);

}  // namespace anchorbench::python
