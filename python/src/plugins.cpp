// Parts written in Python, registered under a name and run by the engine and replay beside the
// built-ins. The engine's threads run C++ without the GIL; a Python part takes the GIL for each
// call, so Python parts run one call at a time whatever the thread count (docs/python.md).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cmath>
#include <set>
#include <type_traits>

#include "anchorbench/estimator/init_trigger.hpp"
#include "anchorbench/estimator/solver.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "anchorbench/schema/names.hpp"
#include "interruptible.hpp"
#include "module_parts.hpp"

namespace anchorbench::python {
namespace {

// The Python threads inside a part's call, by thread id (read and changed with the GIL held), so
// that Ctrl-C can interrupt them (Interruptible).
std::multiset<unsigned long>& RunningPartThreads() {
  static auto* threads = new std::multiset<unsigned long>();  // never destroyed: used until exit
  return *threads;
}

// Marks the calling thread as inside a part for the scope's life; with the GIL held.
class InsidePart {
 public:
  InsidePart() : id_(PyThread_get_thread_ident()) { RunningPartThreads().insert(id_); }
  ~InsidePart() { RunningPartThreads().erase(RunningPartThreads().find(id_)); }
  InsidePart(const InsidePart&) = delete;
  InsidePart& operator=(const InsidePart&) = delete;

 private:
  unsigned long id_;
};

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

// A part's output, checked: `what` if it is not there, of the wrong type or shape, or not finite.
template <typename T>
T Checked(const py::handle& value, const char* what) {
  T out;
  try {
    out = value.cast<T>();
  } catch (const py::cast_error&) {
    throw std::invalid_argument(std::string(what) + " has the wrong type or shape (got " +
                                std::string(py::str(py::repr(value))).substr(0, 80) + ")");
  }
  if constexpr (std::is_same_v<T, double>) {
    if (!std::isfinite(out)) throw std::invalid_argument(std::string(what) + " is not finite");
  } else if constexpr (!std::is_same_v<T, std::string> && !std::is_same_v<T, bool>) {
    if (!out.allFinite()) throw std::invalid_argument(std::string(what) + " is not finite");
  }
  return out;
}

// solve(p_world_tag (N, 3), range_m (N,)) -> (p_world_anchor (3,), bias_m, status) or a dict
// with those keys (and optionally covariance (4, 4)). A result that is not that, or not finite
// with a status that claims an estimate, is refused with the part named.
class PySolver final : public estimator::Solver {
 public:
  PySolver(std::string name, std::shared_ptr<py::function> solve) : name_(std::move(name)), solve_(std::move(solve)) {}

  estimator::SolveResult Solve(std::span<const Eigen::Vector3d> p_world_tag, std::span<const double> range_m) const override {
    py::gil_scoped_acquire acquire;
    const InsidePart inside;
    try {
      return ResultOf((*solve_)(View(p_world_tag), View(range_m)));
    } catch (py::error_already_set& e) {
      Rethrow("solver", name_, e);
    } catch (const std::exception& e) {
      throw std::runtime_error("python solver '" + name_ + "': " + e.what());
    }
  }

 private:
  static estimator::SolveResult ResultOf(const py::object& value) {
    estimator::SolveResult result;
    if (py::isinstance<py::dict>(value)) {
      const py::dict d = value.cast<py::dict>();
      if (!d.contains("p_world_anchor")) throw std::invalid_argument("the dict it returned has no 'p_world_anchor'");
      result.status = StatusOf(d.contains("status") ? Checked<std::string>(d["status"], "status") : "converged");
      if (!estimator::Succeeded(result.status)) return result;  // no estimate claimed: nothing to check
      result.p_world_anchor = Checked<Eigen::Vector3d>(d["p_world_anchor"], "p_world_anchor (3,)");
      result.bias_m = d.contains("bias_m") ? Checked<double>(d["bias_m"], "bias_m") : 0.0;
      if (d.contains("covariance")) result.covariance = Checked<Eigen::Matrix4d>(d["covariance"], "covariance (4, 4)");
      return result;
    }
    if (!py::isinstance<py::tuple>(value) || py::len(value) != 3) {
      throw std::invalid_argument("must return (p_world_anchor, bias_m, status) or a dict, got " +
                                  std::string(py::str(py::repr(value))).substr(0, 80));
    }
    const py::tuple t = value.cast<py::tuple>();
    result.status = StatusOf(Checked<std::string>(t[2], "status"));
    if (!estimator::Succeeded(result.status)) return result;
    result.p_world_anchor = Checked<Eigen::Vector3d>(t[0], "p_world_anchor (3,)");
    result.bias_m = Checked<double>(t[1], "bias_m");
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
    const InsidePart inside;
    try {
      py::dict sample;
      sample["t_s"] = in.t_s;
      sample["t_first_s"] = in.t_first_s;
      sample["n_admitted"] = in.n_admitted;
      sample["pdop"] = in.pdop;
      sample["eligible"] = in.eligible;
      sample["p_world_tag"] = View(in.p_world_tag);
      sample["range_m"] = View(in.range_m);
      return Checked<bool>((*fire_)(sample), "its answer (True or False)");
    } catch (py::error_already_set& e) {
      Rethrow("trigger", name_, e);
    } catch (const std::exception& e) {
      throw std::runtime_error("python trigger '" + name_ + "': " + e.what());
    }
  }

 private:
  std::string name_;
  std::shared_ptr<py::function> fire_;
};

}  // namespace

void InterruptRunningParts() {
  for (const unsigned long id : std::set<unsigned long>(RunningPartThreads().begin(), RunningPartThreads().end())) {
    PyThreadState_SetAsyncExc(id, PyExc_KeyboardInterrupt);
  }
}

namespace {

// A part's name goes into attempts.csv like a row's (schema::NameProblem), and names a built-in
// only if it is one: a name Python registered may be registered again (a notebook's cell run
// twice), a built-in's never.
template <typename Registry>
void CheckPartName(const Registry& registry, std::set<std::string>& from_python, const std::string& kind,
                   const std::string& name) {
  if (const std::string why = schema::NameProblem(name); !why.empty()) throw schema::InputError("name: " + why);
  if (registry.Knows(name) && !from_python.contains(name)) {
    throw schema::InputError("name: '" + name + "' is a built-in " + kind + "; give yours a name of its own");
  }
  from_python.insert(name);
}

std::set<std::string>& PythonSolverNames() {
  static auto* names = new std::set<std::string>();
  return *names;
}
std::set<std::string>& PythonTriggerNames() {
  static auto* names = new std::set<std::string>();
  return *names;
}

}  // namespace

void BindPlugins(py::module_& m) {
  m.def(
      "register_solver",
      [](const std::string& name, py::function solve, const std::string& description) {
        CheckPartName(ModuleComponents().solvers, PythonSolverNames(), "solver", name);
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
        CheckPartName(ModuleComponents().triggers, PythonTriggerNames(), "trigger", name);
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
  m.def(
      "part_options",
      []() {
        py::dict out;
        const auto add = [&](const std::string& section, const auto& parts) {
          for (const auto& [name, options] : parts) {
            py::dict keys;
            for (const registry::OptionSpec& spec : options->specs) {
              py::dict field;
              field["default"] = spec.whole ? py::object(py::int_(static_cast<long long>(spec.default_value)))
                                            : py::object(py::float_(spec.default_value));
              field["description"] = spec.description;
              field["key"] = section + "." + name + "." + spec.key;
              keys[py::str(spec.key)] = field;
            }
            out[py::str(name)] = keys;
          }
        };
        add("estimator", ModuleComponents().PartsWithOptions());
        add("scenario", ModuleComponents().environments.PartsWithOptions());
        return out;
      },
      "The options of the parts that own some (solvers, filters, triggers, environments): "
      "{part: {key: {'default': value, 'description': text, 'key': its config key}}}.");
}

}  // namespace anchorbench::python
