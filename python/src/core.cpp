// The core from Python: solvers and PDOPs on arrays, and the online front end fed one sample at a
// time or in batches. The C++ work runs with the GIL released.
#include <cmath>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "anchorbench/config/load_config.hpp"
#include "anchorbench/engine/attempt.hpp"
#include "anchorbench/estimator/closest_point_pdop.hpp"
#include "anchorbench/estimator/guide.hpp"
#include "anchorbench/estimator/live_front_end.hpp"
#include "anchorbench/estimator/pdop.hpp"
#include "anchorbench/io/format.hpp"
#include "anchorbench/schema/input_error.hpp"
#include "config_handle.hpp"
#include "module_parts.hpp"

namespace anchorbench::python {
namespace {

// An event as one record of a structured array (FrontEnd.take_events_array).
struct EventRecord {
  std::int32_t anchor_id;
  std::int32_t chain;
  double t_s;
  std::int32_t n_used;
  double pdop_closest_point;
  double x, y, z, bias_m;
  char status[24];
};

struct Event {
  int anchor_id = 0;
  std::string trigger;
  estimator::InitEvent init;
};

// A trigger's judgement as a dict: the test that holds the anchor back and by how much, and for
// the certificate its region's terms, the evidence and the stability (None where there is none).
py::dict JudgementDict(int anchor_id, const std::string& trigger, const estimator::Judgement& j) {
  const auto value = [](double v) -> py::object { return std::isnan(v) ? py::object(py::none()) : py::float_(v); };
  py::dict d;
  d["anchor_id"] = anchor_id;
  d["trigger"] = trigger;
  d["t_s"] = value(j.t_s);
  d["samples"] = j.samples;
  d["blocked_by"] = std::string(j.blocked_by);
  using J = estimator::Judgement;
  constexpr std::pair<const char*, double J::*> kNumbers[] = {
      {"value", &J::value},
      {"limit", &J::limit},
      {"region_m", &J::region_m},
      {"share_noise", &J::share_noise},
      {"share_correlation", &J::share_correlation},
      {"share_model_error", &J::share_model_error},
      {"share_travel_bias", &J::share_travel_bias},
      {"share_link_offsets", &J::share_link_offsets},
      {"share_tag_offsets", &J::share_tag_offsets},
      {"evidence", &J::evidence},
      {"evidence_needed", &J::evidence_needed},
      {"evidence_explained", &J::evidence_explained},
      {"stability_m", &J::stability_m},
      {"samples_needed", &J::samples_needed}};
  for (const auto& [key, member] : kNumbers) d[key] = value(j.*member);
  return d;
}

estimator::SolveResult Solve(const Doubles& p_world_tag, const Doubles& range_m, const std::string& solver,
                             const ConfigHandle* config) {
  const std::span<const Eigen::Vector3d> p = Points(p_world_tag, "p_world_tag");
  const std::span<const double> d = Values(range_m, "range_m", static_cast<py::ssize_t>(p.size()));
  // What the initializer's front drops before any solver sees it is refused here, never solved.
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (!(d[k] > 0.0 && std::isfinite(d[k]))) {
      throw schema::InputError("range_m[" + std::to_string(k) + "]: " + io::FormatNumber(d[k]) +
                               " is not a range (a positive, finite distance in metres)");
    }
    if (!p[k].allFinite()) throw schema::InputError("p_world_tag[" + std::to_string(k) + "]: is not finite");
  }
  const schema::EstimatorConfig estimator = config ? config->experiment.estimator : schema::EstimatorConfig{};
  registry::Components& components = ModuleComponents();
  std::string why;
  const std::unique_ptr<estimator::Solver> made =
      components.solvers.Create(solver, {estimator.solver_options, 0, components.tables.get()}, &why);
  if (!made) throw schema::InputError(why);
  py::gil_scoped_release release;
  return made->Solve(p, d);
}

// The online front end with the config's chains (one per trigger), as replay builds them. It is a
// LiveFrontEnd, so any Python thread may call it (each call releases the GIL); without
// defer_solves, the adding call runs the solves it made due before it returns (the inline results).
class PyFrontEnd {
 public:
  PyFrontEnd(const ConfigHandle* config, bool defer_solves)
      : estimator_(config ? config->experiment.estimator : schema::EstimatorConfig{}),
        seed_(config ? config->experiment.seed : 0),
        defer_solves_(defer_solves),
        front_end_(
            [this](int anchor_id) {
              try {
                return registry::MakeChains(ModuleComponents(), anchor_id, estimator_,
                                            engine::SolverSeed(seed_, 0, anchor_id));
              } catch (const std::invalid_argument& e) {
                throw schema::InputError("anchor " + std::to_string(anchor_id) + ": " + e.what());
              }
            },
            {}) {
    std::string why;
    if (!ModuleComponents().Check(estimator_, &why)) throw schema::InputError(why);
  }

  void AddPose(double t_s, int tag_id, const Eigen::Vector3d& p) {
    py::gil_scoped_release release;
    front_end_.AddPose(t_s, tag_id, p);
    SolveUnlessDeferred();
  }
  void AddRange(double t_s, int tag_id, int anchor_id, double range_m) {
    py::gil_scoped_release release;
    front_end_.AddRange(t_s, tag_id, anchor_id, range_m);
    SolveUnlessDeferred();
  }
  void AddSample(double t_s, int tag_id, int anchor_id, double range_m, const Eigen::Vector3d& p) {
    py::gil_scoped_release release;
    front_end_.AddSample({t_s, tag_id, anchor_id, range_m, p});
    SolveUnlessDeferred();
  }
  void AddSamples(const Doubles& t_s, const Ints& tag_id, const Ints& anchor_id, const Doubles& range_m,
                  const Doubles& p_world_tag) {
    const std::span<const Eigen::Vector3d> p = Points(p_world_tag, "p_world_tag");
    const auto n = static_cast<py::ssize_t>(p.size());
    const std::span<const double> t = Values(t_s, "t_s", n), d = Values(range_m, "range_m", n);
    const std::span<const int> tags = IntValues(tag_id, "tag_id", n), anchors = IntValues(anchor_id, "anchor_id", n);
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < p.size(); ++i) {
      front_end_.AddSample({t[i], tags[i], anchors[i], d[i], p[i]});
      SolveUnlessDeferred();
    }
  }
  void AddPoses(const Doubles& t_s, const Ints& tag_id, const Doubles& p_world_tag) {
    const std::span<const Eigen::Vector3d> p = Points(p_world_tag, "p_world_tag");
    const auto n = static_cast<py::ssize_t>(p.size());
    const std::span<const double> t = Values(t_s, "t_s", n);
    const std::span<const int> tags = IntValues(tag_id, "tag_id", n);
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < p.size(); ++i) {
      front_end_.AddPose(t[i], tags[i], p[i]);
      SolveUnlessDeferred();
    }
  }
  void AddRanges(const Doubles& t_s, const Ints& tag_id, const Ints& anchor_id, const Doubles& range_m) {
    const std::span<const double> t = Values(t_s, "t_s");
    const auto n = static_cast<py::ssize_t>(t.size());
    const std::span<const double> d = Values(range_m, "range_m", n);
    const std::span<const int> tags = IntValues(tag_id, "tag_id", n), anchors = IntValues(anchor_id, "anchor_id", n);
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < t.size(); ++i) {
      front_end_.AddRange(t[i], tags[i], anchors[i], d[i]);
      SolveUnlessDeferred();
    }
  }
  std::size_t RunPendingSolves(std::size_t max_count, double budget_s) {
    py::gil_scoped_release release;
    const auto deadline = budget_s > 0.0 && std::isfinite(budget_s)
                              ? estimator::LiveFrontEnd::Clock::now() +
                                    std::chrono::duration_cast<estimator::LiveFrontEnd::Clock::duration>(
                                        std::chrono::duration<double>(budget_s))
                              : estimator::LiveFrontEnd::Clock::time_point::max();
    return front_end_.RunPendingSolves(max_count, deadline);
  }
  void Finish(double t_end_s) {
    py::gil_scoped_release release;
    front_end_.Finish(t_end_s);
  }
  // Every call into the front end releases the GIL first: a Python part runs under its lock and
  // takes the GIL, so holding the GIL while waiting for the lock could deadlock.
  std::vector<estimator::FrontEndEvent> Take() {
    py::gil_scoped_release release;
    return front_end_.TakeEvents();
  }
  std::vector<Event> TakeEvents() {
    std::vector<Event> events;
    for (const estimator::FrontEndEvent& e : Take()) {
      events.push_back({e.anchor_id, estimator_.triggers.at(e.chain), e.init});
    }
    return events;
  }
  py::array TakeEventsArray() {
    const std::vector<estimator::FrontEndEvent> events = Take();
    py::array_t<EventRecord> out(static_cast<py::ssize_t>(events.size()));
    EventRecord* records = out.mutable_data();
    for (std::size_t i = 0; i < events.size(); ++i) {
      const estimator::InitEvent& init = events[i].init;
      EventRecord& r = records[i];
      r = EventRecord{};
      r.anchor_id = events[i].anchor_id;
      r.chain = static_cast<std::int32_t>(events[i].chain);
      r.t_s = init.t_s;
      r.n_used = init.n_used;
      r.pdop_closest_point = init.pdop_closest_point;
      r.x = init.solve.p_world_anchor.x();
      r.y = init.solve.p_world_anchor.y();
      r.z = init.solve.p_world_anchor.z();
      r.bias_m = init.solve.bias_m;
      const std::string_view status = estimator::ToString(init.solve.status);
      status.copy(r.status, std::min(status.size(), sizeof(r.status) - 1));
    }
    return out;
  }
  const std::vector<std::string>& triggers() const { return estimator_.triggers; }
  // Why each anchor's triggers have not fired yet: one record per (anchor, trigger) still waiting.
  py::list WhyNot() const {
    struct Waiting {
      int anchor_id;
      std::size_t chain;
      estimator::Judgement judgement;
    };
    const std::vector<Waiting> waiting = [this] {
      py::gil_scoped_release release;
      return front_end_.Inspect([](const estimator::FrontEnd& front_end) {
        std::vector<Waiting> out;
        for (const int anchor_id : front_end.anchor_ids()) {
          const std::vector<estimator::AnchorInitializer>& chains = front_end.chains(anchor_id);
          for (std::size_t c = 0; c < chains.size(); ++c) {
            if (const std::optional<estimator::Judgement> j = chains[c].why_not()) out.push_back({anchor_id, c, *j});
          }
        }
        return out;
      });
    }();
    py::list out;
    for (const Waiting& w : waiting) out.append(JudgementDict(w.anchor_id, estimator_.triggers.at(w.chain), w.judgement));
    return out;
  }
  // Where each waiting anchor's certificate would have the robot range from next (guidance.hpp).
  py::list Guide(const std::optional<Doubles>& candidates, double samples, std::size_t best, double reach_m, int steps,
                 double range_rate_hz) const {
    estimator::GuideRequest request;
    if (candidates) {
      const std::span<const Eigen::Vector3d> given = Points(*candidates, "candidates");
      request.p_world_candidate.assign(given.begin(), given.end());
    }
    request.samples = samples;
    request.best = best;
    request.reach_m = reach_m;
    request.steps = steps;
    request.range_rate_hz = range_rate_hz;
    const std::vector<estimator::AnchorGuidance> guided = [&] {
      py::gil_scoped_release release;
      return front_end_.Inspect([&](const estimator::FrontEnd& front_end) { return estimator::Guide(front_end, request); });
    }();
    py::list out;
    for (const estimator::AnchorGuidance& g : guided) {
      py::dict d;
      d["anchor_id"] = g.anchor_id;
      d["trigger"] = estimator_.triggers.at(g.chain);
      d["blocked_by"] = std::string(g.blocked_by);
      d["region_m"] = g.region_m;
      d["accuracy_m"] = g.accuracy_m;
      d["seconds_to_certify"] = g.seconds_to_certify;
      py::list ranked;
      for (const estimator::CandidateForecast& c : g.best) {
        py::dict candidate;
        candidate["p_world_candidate"] = Copy(c.p_world_candidate);
        candidate["region_m"] = c.region_m;
        candidate["samples_to_certify"] = c.samples_to_certify;
        ranked.append(candidate);
      }
      d["best"] = ranked;
      out.append(d);
    }
    return out;
  }
  py::dict Counters() const {
    const estimator::FrontEndCounters c = [this] {
      py::gil_scoped_release release;
      return front_end_.counters();
    }();
    py::dict out;
    out["samples"] = c.samples;
    out["ranges_outside_poses"] = c.ranges_outside_poses;
    out["ranges_without_pose"] = c.ranges_without_pose;
    out["poses_ignored"] = c.poses_ignored;
    out["ranges_beyond_max_anchors"] = c.ranges_beyond_max_anchors;
    return out;
  }

 private:
  void SolveUnlessDeferred() {
    if (!defer_solves_) front_end_.RunPendingSolves();
  }

  schema::EstimatorConfig estimator_;
  std::uint64_t seed_;
  bool defer_solves_;
  estimator::LiveFrontEnd front_end_;
};

void BindSolveResult(py::module_& m) {
  py::class_<estimator::SolveResult>(m, "SolveResult", "An anchor estimate: position, range bias, covariance, status.")
      .def_property_readonly("p_world_anchor", [](const estimator::SolveResult& r) { return Copy(r.p_world_anchor); },
                             "the anchor's position (m), shape (3,)")
      .def_readonly("bias_m", &estimator::SolveResult::bias_m, "the anchor's range bias gamma (m)")
      .def_property_readonly("covariance", [](const estimator::SolveResult& r) { return Copy(r.covariance); },
                             "covariance of (p_A, gamma), m^2, shape (4, 4)")
      .def_property_readonly("status", [](const estimator::SolveResult& r) { return std::string(estimator::ToString(r.status)); })
      .def_property_readonly("succeeded", [](const estimator::SolveResult& r) { return estimator::Succeeded(r.status); })
      .def_readonly("alpha", &estimator::SolveResult::alpha, "the kernel shape at the end (2 = L2)")
      .def_readonly("iterations", &estimator::SolveResult::iterations)
      .def_readonly("final_cost", &estimator::SolveResult::final_cost)
      .def("__repr__", [](const estimator::SolveResult& r) {
        return "SolveResult(status=" + std::string(estimator::ToString(r.status)) + ", p_world_anchor=[" +
               std::to_string(r.p_world_anchor.x()) + ", " + std::to_string(r.p_world_anchor.y()) + ", " +
               std::to_string(r.p_world_anchor.z()) + "], bias_m=" + std::to_string(r.bias_m) + ")";
      });
}

void BindFrontEnd(py::module_& m) {
  py::class_<Event>(m, "Event", "An anchor initialized by one trigger.")
      .def_readonly("anchor_id", &Event::anchor_id)
      .def_readonly("trigger", &Event::trigger)
      .def_property_readonly("t_s", [](const Event& e) { return e.init.t_s; })
      .def_property_readonly("n_used", [](const Event& e) { return e.init.n_used; })
      .def_property_readonly("pdop_closest_point", [](const Event& e) { return e.init.pdop_closest_point; })
      .def_property_readonly("solve", [](const Event& e) { return e.init.solve; })
      .def("__repr__", [](const Event& e) {
        return "Event(anchor_id=" + std::to_string(e.anchor_id) + ", trigger=" + e.trigger + ", t_s=" +
               std::to_string(e.init.t_s) + ", status=" + std::string(estimator::ToString(e.init.solve.status)) + ")";
      });
  PYBIND11_NUMPY_DTYPE(EventRecord, anchor_id, chain, t_s, n_used, pdop_closest_point, x, y, z, bias_m, status);
  py::class_<PyFrontEnd>(m, "FrontEnd",
                         "The online front end: poses and ranges in, one initializer per trigger per anchor, events out.")
      .def(py::init<const ConfigHandle*, bool>(), py::arg("config") = nullptr, py::arg("defer_solves") = false)
      .def("add_pose", &PyFrontEnd::AddPose, py::arg("t_s"), py::arg("tag_id"), py::arg("p_world_tag"))
      .def("add_range", &PyFrontEnd::AddRange, py::arg("t_s"), py::arg("tag_id"), py::arg("anchor_id"), py::arg("range_m"))
      .def("add_sample", &PyFrontEnd::AddSample, py::arg("t_s"), py::arg("tag_id"), py::arg("anchor_id"),
           py::arg("range_m"), py::arg("p_world_tag"))
      .def("add_samples", &PyFrontEnd::AddSamples, py::arg("t_s"), py::arg("tag_id"), py::arg("anchor_id"),
           py::arg("range_m"), py::arg("p_world_tag"), "ranges with their tag positions, in time order, as arrays")
      .def("add_poses", &PyFrontEnd::AddPoses, py::arg("t_s"), py::arg("tag_id"), py::arg("p_world_tag"))
      .def("add_ranges", &PyFrontEnd::AddRanges, py::arg("t_s"), py::arg("tag_id"), py::arg("anchor_id"),
           py::arg("range_m"))
      .def("run_pending_solves", &PyFrontEnd::RunPendingSolves,
           py::arg("max_count") = std::numeric_limits<std::size_t>::max(), py::arg("budget_s") = 0.0,
           "runs due solves (with defer_solves), at most max_count, none started after budget_s seconds (0: no limit)")
      .def("finish", &PyFrontEnd::Finish, py::arg("t_end_s"))
      .def("take_events", &PyFrontEnd::TakeEvents)
      .def("take_events_array", &PyFrontEnd::TakeEventsArray,
           "the events as a structured array (anchor_id, chain, t_s, n_used, pdop_closest_point, x, y, z, bias_m, status)")
      .def_property_readonly("triggers", &PyFrontEnd::triggers, "the chains' triggers, by chain index")
      .def("why_not", &PyFrontEnd::WhyNot,
           "why each anchor's triggers wait: one dict per (anchor, trigger) not yet fired, with the test that "
           "holds it back (blocked_by), its value and limit, and for certified the region's terms, the evidence "
           "and the stability (docs/python.md)")
      .def("guide", &PyFrontEnd::Guide, py::arg("candidates") = py::none(), py::arg("samples") = 50.0,
           py::arg("best") = 5, py::arg("reach_m") = 2.0, py::arg("steps") = 2, py::arg("range_rate_hz") = 10.0,
           "where to range from next: for each anchor a certified chain still waits for, its region now and the "
           "best candidates (candidates (M, 3), or a grid reach_m around its last tag position) by the region "
           "after `samples` more ranges there, each with the samples to certify (docs/guidance.md)")
      .def_property_readonly("counters", &PyFrontEnd::Counters);
}

}  // namespace

void BindCore(py::module_& m) {
  BindSolveResult(m);
  m.def("solve", &Solve, py::arg("p_world_tag"), py::arg("range_m"), py::arg("solver") = "lm_adaptive",
        py::arg("config") = nullptr,
        "Solves for an anchor (position and range bias) from tag positions (N, 3) and ranges (N,) with a solver by name.");
  m.def(
      "closest_point_pdop",
      [](const Doubles& p_world_tag, const Doubles& range_m) {
        const std::span<const Eigen::Vector3d> p = Points(p_world_tag, "p_world_tag");
        const std::span<const double> d = Values(range_m, "range_m", static_cast<py::ssize_t>(p.size()));
        estimator::ClosestPointPdop pdop;
        for (std::size_t i = 0; i < p.size(); ++i) pdop.Add(p[i], d[i]);
        return pdop.Value();
      },
      py::arg("p_world_tag"), py::arg("range_m"), "The closest-point PDOP of Eq. (4) over the samples (inf if undefined).");
  m.def(
      "geometry_pdop",
      [](const Doubles& p_world_tag, const Doubles& range_m, const Eigen::Vector3d& p_world_anchor) {
        const std::span<const Eigen::Vector3d> p = Points(p_world_tag, "p_world_tag");
        return estimator::GeometryPdop(p, Values(range_m, "range_m", static_cast<py::ssize_t>(p.size())), p_world_anchor);
      },
      py::arg("p_world_tag"), py::arg("range_m"), py::arg("p_world_anchor"), "The PDOP of the samples at an anchor position.");
  BindFrontEnd(m);
}

}  // namespace anchorbench::python
