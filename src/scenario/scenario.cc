#include "musclesim/scenario/scenario.h"

#include <algorithm>
#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/element_limits.h"

namespace musclesim {

std::shared_ptr<const TensionModel> Scenario::AddModel(const std::string& block, ModelSpec spec) {
  std::shared_ptr<const TensionModel> model = BuildModel(spec);
  models[block] = ScenarioModel{std::move(spec), model};
  return model;
}

void Scenario::SetModel(const std::string& block, ModelSpec spec) {
  ScenarioModel& entry = models.at(block);
  std::shared_ptr<const TensionModel> model = BuildModel(spec);  // throws before any change
  for (Element& element : elements) {
    if (element.model == entry.model) element.model = model;
  }
  entry = ScenarioModel{std::move(spec), std::move(model)};
}

const std::string* Scenario::ModelName(const TensionModel* model) const {
  for (const auto& [block, entry] : models) {
    if (entry.model.get() == model) return &block;
  }
  return nullptr;
}

NetworkSystem Scenario::Build() const {
  std::shared_ptr<const Skeleton> skeleton;
  if (HasSkeleton()) {
    skeleton = std::make_shared<const Skeleton>(bodies, joints, space.gravity, wraps);
  }
  return NetworkSystem(nodes, elements, loads, controllers, space, std::move(skeleton));
}

NetworkRunRequest Scenario::Request() const {
  NetworkRunRequest r;
  r.t_start = t_start;
  r.t_end = t_end;
  r.output_interval = output.every_step ? 0.0 : output.interval;
  r.limits = limits;
  return r;
}

namespace {

// The checks of Validate, with the network's key paths.
// Calls visit(key path, waveform) for every waveform of the scenario.
template <typename Visit>
void ForEachWaveform(const Scenario& s, Visit visit) {
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const std::string at = "nodes[" + std::to_string(i) + "]";
    if (s.nodes[i].kind == NodeKind::kPrescribed) visit(at + ".prescribed", s.nodes[i].motion);
  }
  for (std::size_t i = 0; i < s.elements.size(); ++i) {
    const Element& e = s.elements[i];
    const std::string at = "elements[" + std::to_string(i) + "]";
    if (e.kind != ElementKind::kActuator || e.controlled) continue;
    if (e.excitation) {
      visit(at + ".excitation", e.excitation->signal);
    } else {
      visit(at + ".activation", e.activation);
    }
  }
  for (std::size_t i = 0; i < s.loads.size(); ++i) {
    if (s.loads[i].load.kind == LoadKind::kForce) {
      visit("loads[" + std::to_string(i) + "]", s.loads[i].load.force);
    }
  }
  for (std::size_t i = 0; i < s.controllers.size(); ++i) {
    const Controller& c = s.controllers[i];
    const std::string at = "controllers[" + std::to_string(i) + "]";
    visit(at + ".reference", c.reference);
    visit(at + ".feedforward", c.feedforward);
    if (c.co_contraction) visit(at + ".co_contraction.level", c.co_contraction->level);
  }
}

// The request's names for the span and grid, as the file's keys.
std::string RequestKey(const std::string& path) {
  if (path == "t_start") return "time.start";
  if (path == "t_end") return "time.end";
  if (path == "output_interval") return "output.interval";
  return path;
}

void ValidateNetwork(const Scenario& s) {
  try {
    Validate(s.solver);
  } catch (const ParameterError& error) {
    throw ParameterError("solver." + error.path(), error.value(), error.rule());
  }
  try {
    Validate(s.Request());
  } catch (const ParameterError& error) {
    throw ParameterError(RequestKey(error.path()), error.value(), error.rule());
  }
  const NetworkSystem system = s.Build();
  std::vector<double> y(static_cast<std::size_t>(system.state_size()));
  system.InitialState(s.t_start, y.data());
  system.CheckInitialState(s.t_start, y.data());
  // the single actuator's element starts at its initial.length
  const std::string initial = InitialLengthName(s);
  for (std::size_t i = 0; i < s.limits.size(); ++i) {
    const LengthLimit& limit = s.limits[i];
    const std::string at = "limits[" + std::to_string(i) + "]";
    const int e = system.FindElement(limit.element);
    if (e < 0) throw ParameterError(at + ".element", limit.element, "names no element");
    const double length = system.Length(e, s.t_start, y.data());
    if (limit.min_length) {
      Require(*limit.min_length >= 0.0 && *limit.min_length < length, at + ".min_length",
              *limit.min_length,
              "must be >= 0 and below " + initial + " = " + FormatNumber(length) + " [m]");
    }
    if (limit.max_length) {
      Require(*limit.max_length > length, at + ".max_length", *limit.max_length,
              "must be above " + initial + " = " + FormatNumber(length) + " [m]");
      // the run may reach this length: its law must stay finite up to it
      const double tension =
          TensionAtRest(system.elements()[static_cast<std::size_t>(e)], *limit.max_length);
      Require(std::isfinite(tension), at + ".max_length", *limit.max_length,
              "is a length the run may reach, and there the tension of " + limit.element +
                  " overflows (" + FormatNumber(tension) +
                  " N): an exponential's alpha times its stretch must stay below about 700");
    }
  }
  ForEachWaveform(s, [&](const std::string& path, const Waveform& w) {
    try {
      CheckPulseTrain(w, s.t_start, s.t_end);
    } catch (const ParameterError& error) {
      throw ParameterError(path + "." + error.path(), error.value(), error.rule());
    }
  });
  if (s.solver.linear_solver == LinearSolverKind::kSmall &&
      system.state_size() > kSmallSystemMaxSize) {
    throw ParameterError("solver.linear_solver", "small",
                         "serves at most " + std::to_string(kSmallSystemMaxSize) +
                             " states and this network has " + std::to_string(system.state_size()) +
                             ": use auto, dense, band or sparse");
  }
}

}  // namespace

void Scenario::Validate() const {
  try {
    ValidateNetwork(*this);
  } catch (const ParameterError& error) {
    throw ParameterError(FileKeyPath(*this, error.path()), error.value(), error.rule());
  }
}

double Scenario::PhaseTolerance(int e) const {
  if (output.phase_tolerance) return *output.phase_tolerance;
  return elements[static_cast<std::size_t>(e)].model->params().velocity.epsilon;
}

}  // namespace musclesim
