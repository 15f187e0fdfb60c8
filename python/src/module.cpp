// The Python module `anchorbench._anchorbench` (docs/python.md). The package's __init__.py turns
// its results into pandas DataFrames.
#include "anchorbench/eval/oracles.hpp"
#include "anchorbench/example_parts/example_parts.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "module_parts.hpp"

namespace anchorbench::python {

registry::Components& ModuleComponents() {
  static registry::Components* components = [] {
    auto* parts = new registry::Components(eval::MakeComponentsWithOracles());
    example_parts::RegisterExampleParts(*parts);
    return parts;
  }();
  return *components;
}

std::span<const Eigen::Vector3d> Points(const Doubles& array, const char* what) {
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw schema::InputError(std::string(what) + ": expected an array of shape (N, 3)");
  }
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d is three packed doubles");
  return {reinterpret_cast<const Eigen::Vector3d*>(array.data()), static_cast<std::size_t>(array.shape(0))};
}

namespace {

template <typename T>
std::span<const T> OneAxis(const py::array_t<T, py::array::c_style | py::array::forcecast>& array, const char* what,
                           py::ssize_t n) {
  if (array.ndim() != 1 || (n >= 0 && array.shape(0) != n)) {
    throw schema::InputError(std::string(what) + ": expected an array of shape (" + (n >= 0 ? std::to_string(n) : "N") +
                             ",)");
  }
  return {array.data(), static_cast<std::size_t>(array.shape(0))};
}

}  // namespace

std::span<const double> Values(const Doubles& array, const char* what, py::ssize_t n) { return OneAxis(array, what, n); }
std::span<const int> IntValues(const Ints& array, const char* what, py::ssize_t n) { return OneAxis(array, what, n); }

namespace {

py::array ReadOnly(py::array array) {
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

}  // namespace

py::array View(std::span<const Eigen::Vector3d> points) {
  // A base object makes numpy borrow the memory instead of copying it.
  return ReadOnly(py::array_t<double>({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}},
                                      reinterpret_cast<const double*>(points.data()), py::none()));
}

py::array View(std::span<const double> values) {
  return ReadOnly(py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data(), py::none()));
}

py::array Copy(const Eigen::Vector3d& v) { return py::array_t<double>(py::ssize_t{3}, v.data()); }

py::array Copy(const Eigen::Matrix4d& m) {
  py::array_t<double> out({py::ssize_t{4}, py::ssize_t{4}});
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) out.mutable_at(i, j) = m(i, j);
  }
  return out;
}

}  // namespace anchorbench::python

PYBIND11_MODULE(_anchorbench, m) {
  namespace ab = anchorbench::python;
  m.doc() = "anchorbench: online UWB anchor initialization (Delama et al., IROS 2025), its core and its trials";
  // The CLI's one-line message (file:line or key) as a Python exception.
  static ab::py::exception<anchorbench::schema::InputError> input_error(m, "InputError", PyExc_ValueError);
  ab::py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const anchorbench::schema::InputError& e) {
      input_error(e.what());
    }
  });
  ab::BindTrials(m);  // first: Config, which the core's functions take
  ab::BindCore(m);
  ab::BindPlugins(m);
}
