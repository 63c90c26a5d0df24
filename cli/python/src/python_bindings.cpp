// The extension module wpg._wpg: the engine's runs, studies and stored runs, and libwpg's online
// generator, for the Python package cli/python/wpg/ (which builds the public API on it).
// The one file that includes pybind11 (a heavy header). Arrays of a run are numpy views of the
// C++ result's buffers (read-only, the run's core object as their base: nothing copied); the
// small tables (footsteps, NMPC log) are copied once into columns. Walks, studies and saves
// run without the GIL.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "engine_calls.hpp"
#include "online_session.hpp"
#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/nmpc/extension_registry.hpp"
#include "wpg/walk_trajectory.hpp"

namespace py = pybind11;

namespace wpg::python {
namespace {

// The registered extensions of one kind (wpg/nmpc/extension_registry.hpp) as
// [{"name", "description", "parameters": [{"name", "unit", "description", "required",
// "default"}]}], sorted by name.
template <class Spec>
py::list extensionList(const std::vector<Spec>& specs) {
  py::list list;
  for (const Spec& spec : specs) {
    py::list parameters;
    for (const ExtensionParameter& p : spec.parameters) {
      py::dict parameter;
      parameter["name"] = p.name;
      parameter["unit"] = p.unit;
      parameter["description"] = p.description;
      parameter["required"] = p.required;
      parameter["default"] = p.required ? py::object(py::none()) : py::float_(p.default_value);
      parameters.append(parameter);
    }
    py::dict entry;
    entry["name"] = spec.name;
    entry["description"] = spec.description;
    entry["parameters"] = parameters;
    list.append(entry);
  }
  return list;
}

// A read-only view of rows x cols doubles at `data` (strides in bytes) kept alive by `base`.
template <typename T>
py::array view(const py::handle& base, const T* data, py::ssize_t rows, py::ssize_t cols,
               py::ssize_t row_stride, py::ssize_t col_stride) {
  static const T empty{};
  py::array array =
      cols == 0 ? py::array_t<T>({rows}, {row_stride}, rows ? data : &empty, base)
                : py::array_t<T>({rows, cols}, {row_stride, col_stride}, rows ? data : &empty, base);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

template <typename Vector>
py::array rowsView(const py::handle& base, const std::vector<Vector>& rows) {
  return view<double>(base, rows.empty() ? nullptr : rows.front().data(),
                      static_cast<py::ssize_t>(rows.size()), Vector::RowsAtCompileTime,
                      sizeof(Vector), sizeof(double));
}

py::object matrixView(const py::handle& base, const Eigen::MatrixXd& m) {
  if (m.size() == 0) return py::none();
  return view<double>(base, m.data(), m.rows(), m.cols(), sizeof(double),
                      m.rows() * static_cast<py::ssize_t>(sizeof(double)));
}

const char* supportName(SupportState support) {
  switch (support) {
    case SupportState::kLeft: return "left";
    case SupportState::kRight: return "right";
    default: return "double";
  }
}

py::array walkArray(const py::object& self, const std::string& name) {
  const RunSession& run = self.cast<const RunSession&>();
  const WalkTrajectory& w = run.result.walk.result.trajectory;
  const auto n = static_cast<py::ssize_t>(w.size());
  if (name == "time") return view<double>(self, w.time.data(), n, 0, sizeof(double), 0);
  if (name == "com") return rowsView(self, w.com);
  if (name == "com_vel") return rowsView(self, w.com_vel);
  if (name == "com_acc") return rowsView(self, w.com_acc);
  if (name == "cop") return rowsView(self, w.cop);
  if (name == "left_foot") return rowsView(self, w.left_foot);
  if (name == "right_foot") return rowsView(self, w.right_foot);
  if (name == "free_flyer_yaw") {
    return view<double>(self, w.free_flyer_yaw.data(), n, 0, sizeof(double), 0);
  }
  if (name == "support") {
    static_assert(sizeof(SupportState) == 1, "support codes are stored as u1");
    return view<std::uint8_t>(self, reinterpret_cast<const std::uint8_t*>(w.support.data()), n,
                              0, 1, 0);
  }
  throw std::invalid_argument("no walk array '" + name + "'");
}

py::object replayArray(const py::object& self, const std::string& name) {
  const RunSession& run = self.cast<const RunSession&>();
  if (!run.result.replay) return py::none();
  const MultibodyValidation& v = run.result.replay->validation;
  if (name == "q") return matrixView(self, v.q);
  if (name == "zmp_multibody") return matrixView(self, v.zmp_multibody);
  if (name == "com_filtered") return matrixView(self, v.com_filtered);
  if (name == "zmp_multibody_filtered") return matrixView(self, v.zmp_multibody_filtered);
  throw std::invalid_argument("no replay array '" + name + "'");
}

py::dict replaySummary(const RunSession& run) {
  py::dict out;
  if (!run.result.replay) return out;
  const MultibodyValidation& v = run.result.replay->validation;
  out["configuration_names"] = v.configuration_names;
  out["zmp_error_rms_before"] = v.before.rms;
  out["zmp_error_max_before"] = v.before.max;
  out["zmp_error_rms_after"] = v.after.rms;
  out["zmp_error_max_after"] = v.after.max;
  out["ik_failures"] = v.ik_failures;
  out["filter_mode"] = v.filter_mode;
  out["wall_time"] = run.result.replay->wall_time;
  return out;
}

// Footsteps as columns (one copy): landing_time, x, y, yaw, side.
py::dict footstepColumns(const RunSession& run) {
  const std::vector<Footstep>& steps = run.result.walk.result.trajectory.footsteps;
  const auto m = static_cast<py::ssize_t>(steps.size());
  py::array_t<double> landing(m), x(m), y(m), yaw(m);
  py::list side;
  for (py::ssize_t i = 0; i < m; ++i) {
    landing.mutable_at(i) = steps[i].landing_time;
    x.mutable_at(i) = steps[i].pose.x();
    y.mutable_at(i) = steps[i].pose.y();
    yaw.mutable_at(i) = steps[i].pose.z();
    side.append(steps[i].side == FootSide::kLeft ? "left" : "right");
  }
  py::dict out;
  out["landing_time"] = landing;
  out["x"] = x;
  out["y"] = y;
  out["yaw"] = yaw;
  out["side"] = side;
  return out;
}

// The NMPC log as columns (one copy), with one slack column per constraint family.
py::dict mpcColumns(const RunSession& run) {
  const WalkTrajectory& w = run.result.walk.result.trajectory;
  const auto k = static_cast<py::ssize_t>(w.mpc.size());
  py::array_t<double> time(k), solve_time(k), cost(k), commanded_vx(k), commanded_vy(k);
  py::array_t<std::int32_t> qp(k), sqp(k);
  py::array_t<std::uint8_t> code(k), relaxed(k);
  const auto families = static_cast<py::ssize_t>(w.constraint_families.size());
  std::vector<py::array_t<double>> slack;
  for (py::ssize_t f = 0; f < families; ++f) slack.emplace_back(k);
  py::list status;
  for (py::ssize_t i = 0; i < k; ++i) {
    const MpcIterationLog& log = w.mpc[i];
    time.mutable_at(i) = log.time;
    solve_time.mutable_at(i) = log.solve_time;
    cost.mutable_at(i) = log.cost;
    commanded_vx.mutable_at(i) = log.commanded_velocity.x();
    commanded_vy.mutable_at(i) = log.commanded_velocity.y();
    qp.mutable_at(i) = log.qp_iterations;
    sqp.mutable_at(i) = log.sqp_iterations;
    code.mutable_at(i) = static_cast<std::uint8_t>(log.status);
    relaxed.mutable_at(i) = static_cast<std::uint8_t>(log.relaxed_families);
    status.append(iterationStatusName(log.status));
    for (py::ssize_t f = 0; f < families && f < kMaxConstraintFamilies; ++f) {
      slack[f].mutable_at(i) = log.slack[f];
    }
  }
  py::dict out;
  out["time"] = time;
  out["status"] = status;
  out["status_code"] = code;
  out["solve_time"] = solve_time;
  out["qp_iterations"] = qp;
  out["sqp_iterations"] = sqp;
  out["cost"] = cost;
  out["relaxed_families"] = relaxed;
  out["commanded_vx"] = commanded_vx;
  out["commanded_vy"] = commanded_vy;
  for (py::ssize_t f = 0; f < families; ++f) {
    out[py::str("slack_" + w.constraint_families[f].name)] = slack[f];
  }
  return out;
}

// What each NMPC iteration predicted (mpc/plan/ of the dataset), shaped per iteration (one
// copy): the package's wpg.Plans. Empty arrays when the run did not record it.
template <typename T>
py::array_t<T> shaped(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::ssize_t size = 1;
  for (const py::ssize_t n : shape) size *= n;
  if (static_cast<py::ssize_t>(values.size()) != size) shape.assign(1, 0);
  py::array_t<T> out(shape);
  std::copy(values.begin(), values.begin() + out.size(), out.mutable_data());
  return out;
}

py::dict planColumns(const PlanLog& p) {
  const py::ssize_t k = static_cast<py::ssize_t>(p.size()), n = p.max_samples, s = p.steps;
  py::dict out;
  out["sampling_period"] = p.sampling_period;
  out["sample_count"] = shaped(p.samples, {k});
  out["com"] = shaped(p.com_position, {k, n, 2});
  out["com_vel"] = shaped(p.com_velocity, {k, n, 2});
  out["com_acc"] = shaped(p.com_acceleration, {k, n, 2});
  out["jerk"] = shaped(p.jerk, {k, n, 2});
  out["cop"] = shaped(p.cop, {k, n, 2});
  out["steps"] = shaped(p.step, {k, s, 4});
  out["step_side"] = shaped(p.step_side, {k, s});
  out["active_rows"] = shaped(p.active_rows, {k, static_cast<py::ssize_t>(p.families)});
  return out;
}

// One online step's plan: the same arrays for one iteration, cut to its samples.
py::object onlinePlan(const OnlineStep& step) {
  if (!step.plan) return py::none();
  const NmpcPlan& p = *step.plan;
  PlanLog log;
  log.reserve(p.samples, static_cast<int>(p.step_pose.rows()),
              static_cast<int>(p.active_rows.size()), p.sampling_period, 1);
  log.append(p);
  const py::dict columns = planColumns(log);
  py::dict out;
  for (const auto& item : columns) {  // the one iteration's row of each array
    out[item.first] = py::isinstance<py::array>(item.second) ? item.second[py::int_(0)]
                                                              : py::reinterpret_borrow<py::object>(item.second);
  }
  out["time"] = p.time;
  return out;
}

// One column per field of the route plans (routePlans), the routes as (k, 3) arrays.
py::dict routePlanColumns(const RunSession& run) {
  const std::vector<datasets::StoredRoutePlan> plans = routePlans(run);
  py::list time, trigger, status, planning_time, route_length, solution_length, simplified,
      clearance, simplification_time, graph_states, graph_motions, route;
  for (const datasets::StoredRoutePlan& plan : plans) {
    time.append(plan.time);
    trigger.append(plan.trigger_name);
    status.append(plan.status_name);
    planning_time.append(plan.planning_time);
    route_length.append(plan.route_length);
    solution_length.append(plan.solution_length);
    simplified.append(plan.simplified_solution_length);
    clearance.append(plan.solution_clearance);
    simplification_time.append(plan.simplification_time);
    graph_states.append(plan.graph_states);
    graph_motions.append(plan.graph_motions);
    py::array_t<double> points({static_cast<py::ssize_t>(plan.route.size()), py::ssize_t{3}});
    for (std::size_t i = 0; i < plan.route.size(); ++i)
      for (int c = 0; c < 3; ++c) points.mutable_at(i, c) = plan.route[i][c];
    route.append(points);
  }
  py::dict out;
  out["time"] = time;
  out["trigger"] = trigger;
  out["status"] = status;
  out["planning_time"] = planning_time;
  out["route_length"] = route_length;
  out["solution_length"] = solution_length;
  out["simplified_solution_length"] = simplified;
  out["solution_clearance"] = clearance;
  out["simplification_time"] = simplification_time;
  out["graph_states"] = graph_states;
  out["graph_motions"] = graph_motions;
  out["route"] = route;
  return out;
}

py::list constraintFamilies(const RunSession& run) {
  py::list out;
  for (const ConstraintFamilyInfo& family : run.result.walk.result.trajectory.constraint_families) {
    out.append(py::make_tuple(family.name, family.unit, family.group));
  }
  return out;
}

// (name, value, unit, integer, wall_time) per metric of datasets/METRICS.md, in table order.
py::list metricRows(const analysis::RunMetrics* metrics) {
  py::list out;
  for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
    out.append(py::make_tuple(metric.name, metrics ? py::object(py::float_(metrics->*metric.field))
                                                   : py::object(py::none()),
                              metric.unit, metric.integer, metric.wall_time));
  }
  return out;
}

// A control sample with the status of the last NMPC iteration, copied out of the generator.
// Python's signal pending (Ctrl-C) after a run: the study stops (engine_calls.hpp, StopCheck).
struct Interrupted {};

// `study(stop)` without the GIL; a signal Python got meanwhile (its handler runs on the main
// thread only: asked from the calling thread, which delivers the runs between its own) stops
// it, and its exception (KeyboardInterrupt) is raised here.
template <typename Study>
StudyFiles interruptible(const Study& study) {
  const std::thread::id caller = std::this_thread::get_id();
  const StopCheck stop = [caller] {
    if (std::this_thread::get_id() != caller) return;
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw Interrupted{};
  };
  try {
    const py::gil_scoped_release release;
    return study(stop);
  } catch (const Interrupted&) {
    throw py::error_already_set();  // the exception PyErr_CheckSignals set
  }
}

py::array vectorCopy(const double* data, py::ssize_t n) { return py::array_t<double>(n, data); }

void bindOnline(py::module_& m) {
  py::class_<OnlineStep>(m, "OnlineState")
      .def_property_readonly("time", [](const OnlineStep& s) { return s.sample.time; })
      .def_property_readonly("com", [](const OnlineStep& s) { return vectorCopy(s.sample.com_position.data(), 3); })
      .def_property_readonly("com_vel", [](const OnlineStep& s) { return vectorCopy(s.sample.com_velocity.data(), 3); })
      .def_property_readonly("com_acc", [](const OnlineStep& s) { return vectorCopy(s.sample.com_acceleration.data(), 3); })
      .def_property_readonly("cop", [](const OnlineStep& s) { return vectorCopy(s.sample.cop.data(), 2); })
      .def_property_readonly("left_foot", [](const OnlineStep& s) { return vectorCopy(s.sample.left_foot.data(), 4); })
      .def_property_readonly("right_foot", [](const OnlineStep& s) { return vectorCopy(s.sample.right_foot.data(), 4); })
      .def_property_readonly("support", [](const OnlineStep& s) { return supportName(s.sample.support); })
      .def_property_readonly("free_flyer_yaw", [](const OnlineStep& s) { return s.sample.free_flyer_yaw; })
      .def_property_readonly("nmpc_sample", [](const OnlineStep& s) { return s.sample.nmpc_sample; })
      .def_property_readonly("status", [](const OnlineStep& s) { return iterationStatusName(s.status); })
      .def_property_readonly("fallen", [](const OnlineStep& s) { return s.fallen; })
      .def_property_readonly("landed", [](const OnlineStep& s) { return s.landed; })
      .def_property_readonly("plan", &onlinePlan);

  py::class_<OnlineSession>(m, "OnlineCore")
      .def(py::init([](const std::string& scenario, std::vector<std::string> overrides) {
             return std::make_unique<OnlineSession>(loadOnlineScenario(scenario, overrides));
           }),
           py::arg("scenario"), py::arg("overrides"))
      // Every call of a session takes its lock with the GIL released (online_session.hpp):
      // threads sharing one generator wait for each other's step, not for Python.
      .def("step",
           [](OnlineSession& session, py::object command) {
             std::optional<Eigen::Vector3d> given;
             if (!command.is_none()) {
               const auto values = command.cast<std::vector<double>>();
               if (values.size() != 3) {
                 throw datasets::InputError("command: expected (vx, vy, omega), 3 numbers, got " +
                                            std::to_string(values.size()));
               }
               given = Eigen::Vector3d(values[0], values[1], values[2]);
             }
             py::gil_scoped_release release;
             return session.step(given ? &*given : nullptr);
           },
           py::arg("command") = py::none())
      // `steps` control periods with `command` entirely in C++ (what gen.step() costs without
      // Python: benchmarks/bench_python_overhead.py); returns their wall time [s].
      .def("run_steps",
           [](OnlineSession& session, const std::vector<double>& command, int steps) {
             if (command.size() != 3) throw datasets::InputError("command: expected 3 numbers");
             const Eigen::Vector3d c(command[0], command[1], command[2]);
             py::gil_scoped_release release;
             return session.runSteps(c, steps);
           },
           py::arg("command"), py::arg("steps"))
      .def("set_obstacles", &OnlineSession::setObstacles, py::arg("yaml"),
           py::call_guard<py::gil_scoped_release>())
      .def("push",
           [](OnlineSession& s, double fx, double fy, double duration) {
             s.push(Eigen::Vector2d(fx, fy), duration);
           },
           py::call_guard<py::gil_scoped_release>())
      .def("reset",
           [](OnlineSession& s, double x, double y, double yaw) { s.reset({x, y, yaw}); },
           py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("time", [](const OnlineSession& s) {
        py::gil_scoped_release release;
        return s.time();
      })
      .def_property_readonly("control_period", &OnlineSession::controlPeriod)
      .def_property_readonly("command", [](const OnlineSession& s) {
        Eigen::Vector3d command;
        {
          py::gil_scoped_release release;
          command = s.command();
        }
        return vectorCopy(command.data(), 3);
      });
}

void bindRun(py::module_& m) {
  py::class_<RunSession, std::shared_ptr<RunSession>>(m, "RunCore")
      .def_property_readonly("name", [](const RunSession& r) { return r.loaded.scenario.name; })
      .def_property_readonly("success",
                             [](const RunSession& r) { return r.result.exitStatus() == 0; })
      .def_property_readonly("exit_code", [](const RunSession& r) { return r.result.exitStatus(); })
      .def_property_readonly(
          "outcome", [](const RunSession& r) { return engine::runOutcomeName(r.result.outcome); })
      .def_property_readonly("message",
                             [](const RunSession& r) { return r.result.walk.result.message; })
      .def_property_readonly("blocked",
                             [](const RunSession& r) { return r.result.walk.result.blocked; })
      .def_property_readonly("blocked_since",
                             [](const RunSession& r) -> py::object {
                               const WalkResult& walk = r.result.walk.result;
                               if (!walk.blocked) return py::none();
                               return py::float_(walk.blocked_since);
                             })
      .def_property_readonly("blocked_position",
                             [](const RunSession& r) -> py::object {
                               const WalkResult& walk = r.result.walk.result;
                               if (!walk.blocked) return py::none();
                               return py::make_tuple(walk.blocked_position.x(),
                                                     walk.blocked_position.y());
                             })
      .def_property_readonly(
          "scenario_yaml",
          [](const RunSession& r) { return resolvedScenarioText(r.loaded.scenario); })
      .def_property_readonly("warnings",
                             [](const RunSession& r) { return r.loaded.scenario.warnings; })
      .def_property_readonly("scenario_path", [](const RunSession& r) { return r.loaded.path; })
      .def_property_readonly("stored_file", [](const RunSession& r) { return r.stored_file; })
      .def_property_readonly("replayed",
                             [](const RunSession& r) { return r.result.replay.has_value(); })
      .def("walk_array", &walkArray)
      .def("replay_array", &replayArray)
      .def("replay_summary", &replaySummary)
      .def("footstep_columns", &footstepColumns)
      .def("mpc_columns", &mpcColumns)
      .def("constraint_families", &constraintFamilies)
      .def("plan_columns",
           [](const RunSession& r) { return planColumns(r.result.walk.result.trajectory.plans); })
      .def("route_plan_columns", &routePlanColumns)
      .def("metric_rows", [](const RunSession& r) { return metricRows(&r.result.metrics); })
      .def("save", &saveRun, py::arg("path"), py::call_guard<py::gil_scoped_release>());
}

}  // namespace
}  // namespace wpg::python

PYBIND11_MODULE(_wpg, m) {
  using namespace wpg::python;
  m.doc() = "The C++ side of the wpg package (see the package wpg for the documented API).";
  static py::exception<wpg::datasets::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const wpg::datasets::InputError& e) {
      input_error(e.what());
    }
  });
  bindRun(m);
  bindOnline(m);
  m.def("run", &runScenarioFile, py::arg("scenario"), py::arg("overrides"), py::arg("replay"),
        py::arg("filter"), py::call_guard<py::gil_scoped_release>());
  m.def("load_run", &loadStoredRun, py::arg("path"), py::arg("name"),
        py::call_guard<py::gil_scoped_release>());
  m.def("run_names", &storedRunNames, py::arg("path"));
  m.def("check_stored_strings", &checkStoredStrings, py::arg("path"), py::arg("group") = "/");
  m.def("batch",
        [](const std::string& study, const std::string& output, int jobs, bool resume,
           bool figure, const std::optional<std::vector<std::string>>& fields) {
          const StudyFiles files = interruptible([&](const StopCheck& stop) {
            return runBatch(study, output, jobs, resume, figure, fields, stop);
          });
          return py::make_tuple(files.batch_file, files.runs, files.failed_runs);
        },
        py::arg("study"), py::arg("output"), py::arg("jobs"), py::arg("resume"),
        py::arg("figure"), py::arg("fields"));
  m.def("compare",
        [](const std::string& study, const std::string& folder, int jobs, bool figures) {
          const StudyFiles files = interruptible([&](const StopCheck& stop) {
            return runCompare(study, folder, jobs, figures, stop);
          });
          return py::make_tuple(files.batch_file, files.runs);
        },
        py::arg("study"), py::arg("folder"), py::arg("jobs"),
        py::arg("figures"));
  m.def("scenarios", &shippedScenarioNames);
  m.def("resolve_scenario", &resolveScenarioPath, py::arg("scenario"));
  m.def("data_directory", &dataDirectory);
  m.def("metric_table", [] { return metricRows(nullptr); });
  m.def("families", [] { return extensionList(wpg::registeredConstraintFamilies()); });
  m.def("costs", [] { return extensionList(wpg::registeredCostTerms()); });
}
