// Parts written in Python, registered under a name and run by the engine and replay beside the
// built-ins. The engine's threads run C++ without the GIL; a Python part takes the GIL for each
// call, so Python parts run one call at a time whatever the thread count (docs/python.md).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/solver.hpp"
#include "module_parts.hpp"

namespace anchorbench::python {
namespace {

// A Python callable kept for the life of the process: the registry holds it past any scope, and
// it must never be released without the GIL (at exit, after the interpreter).
std::shared_ptr<py::function> Keep(py::function function) {
  return std::shared_ptr<py::function>(new py::function(std::move(function)), [](py::function*) {});
}

// The error of a Python part as a C++ one (a Python error must not cross the engine's threads).
[[noreturn]] void Rethrow(const std::string& kind, const std::string& name, const py::error_already_set& e) {
  throw std::runtime_error("python " + kind + " '" + name + "': " + e.what());
}

estimator::SolveStatus StatusOf(const std::string& name) {
  estimator::SolveStatus status = estimator::SolveStatus::kNumericalFailure;
  if (!estimator::kSolveStatusNames.Parse(name, &status)) {
    throw std::runtime_error("status '" + name + "' is not one of " + estimator::kSolveStatusNames.Choices());
  }
  return status;
}

// solve(p_world_tag (N, 3), range_m (N,)) -> (p_world_anchor (3,), bias_m, status) or a dict
// with those keys (and optionally covariance (4, 4)).
class PySolver final : public estimator::Solver {
 public:
  PySolver(std::string name, std::shared_ptr<py::function> solve) : name_(std::move(name)), solve_(std::move(solve)) {}

  estimator::SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override {
    py::gil_scoped_acquire acquire;
    try {
      return ResultOf((*solve_)(View(p_world_tag), View(range_m)));
    } catch (py::error_already_set& e) {
      Rethrow("solver", name_, e);
    } catch (const py::cast_error& e) {
      throw std::runtime_error("python solver '" + name_ + "': " + e.what());
    }
  }

 private:
  static estimator::SolveResult ResultOf(const py::object& value) {
    estimator::SolveResult result;
    if (py::isinstance<py::dict>(value)) {
      const py::dict d = value.cast<py::dict>();
      result.p_world_anchor = d["p_world_anchor"].cast<Eigen::Vector3d>();
      result.bias_m = d.contains("bias_m") ? d["bias_m"].cast<double>() : 0.0;
      result.status = StatusOf(d.contains("status") ? d["status"].cast<std::string>() : "converged");
      if (d.contains("covariance")) result.covariance = d["covariance"].cast<Eigen::Matrix4d>();
      return result;
    }
    const py::tuple t = value.cast<py::tuple>();
    result.p_world_anchor = t[0].cast<Eigen::Vector3d>();
    result.bias_m = t[1].cast<double>();
    result.status = StatusOf(t[2].cast<std::string>());
    return result;
  }

  std::string name_;
  std::shared_ptr<py::function> solve_;
};

// fire(sample) -> bool, once per accepted sample, where `sample` holds the trigger's view:
// t_s, t_first_s, n_admitted, pdop, eligible, and the buffered p_world_tag (N, 3) and range_m
// (N,) as read-only views valid during the call.
class PyTrigger final : public estimator::InitTrigger {
 public:
  PyTrigger(std::string name, std::shared_ptr<py::function> fire) : name_(std::move(name)), fire_(std::move(fire)) {}

  bool Fire(const estimator::TriggerInput& in) override {
    py::gil_scoped_acquire acquire;
    try {
      py::dict sample;
      sample["t_s"] = in.t_s;
      sample["t_first_s"] = in.t_first_s;
      sample["n_admitted"] = in.n_admitted;
      sample["pdop"] = in.pdop;
      sample["eligible"] = in.eligible;
      sample["p_world_tag"] = View(in.p_world_tag);
      sample["range_m"] = View(in.range_m);
      return (*fire_)(sample).cast<bool>();
    } catch (py::error_already_set& e) {
      Rethrow("trigger", name_, e);
    } catch (const py::cast_error& e) {
      throw std::runtime_error("python trigger '" + name_ + "': " + e.what());
    }
  }

 private:
  std::string name_;
  std::shared_ptr<py::function> fire_;
};

}  // namespace

void BindPlugins(py::module_& m) {
  m.def(
      "register_solver",
      [](const std::string& name, py::function solve, const std::string& description) {
        const std::shared_ptr<py::function> kept = Keep(std::move(solve));
        ModuleComponents().solvers.Register(name, description.empty() ? "a solver written in Python" : description,
                                            [name, kept](const std::string&, const registry::SolverContext&) {
                                              return std::make_unique<PySolver>(name, kept);
                                            });
      },
      py::arg("name"), py::arg("solve"), py::arg("description") = "",
      "Registers solve(p_world_tag, range_m) -> (p_world_anchor, bias_m, status) under `name`, for configs,"
      " run, sweep, replay and FrontEnd.");
  m.def(
      "register_trigger",
      [](const std::string& name, py::function fire, const std::string& description) {
        const std::shared_ptr<py::function> kept = Keep(std::move(fire));
        ModuleComponents().triggers.Register(name, description.empty() ? "a trigger written in Python" : description,
                                             [name, kept](const std::string&, const registry::TriggerContext&) {
                                               return std::make_unique<PyTrigger>(name, kept);
                                             });
      },
      py::arg("name"), py::arg("fire"), py::arg("description") = "",
      "Registers fire(sample) -> bool under `name`: the anchor is solved once it returns True.");
  m.def(
      "parts",
      []() {
        const registry::Components& c = ModuleComponents();
        py::dict out;
        out["solvers"] = c.solvers.List();
        out["filters"] = c.filters.List();
        out["triggers"] = c.triggers.List();
        return out;
      },
      "The parts a config can name: {kind: [(name, description), ...]}.");
}

}  // namespace anchorbench::python
