#include "io/sensitivity_setup.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "io/key_path.h"
#include "io/yaml_fields.h"
#include "io/yaml_override.h"
#include "musclesim/errors.h"
#include "musclesim/io/network_scenario.h"
#include "musclesim/io/network_scenario_template.h"
#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"
#include "musclesim/model/number_format.h"

namespace musclesim {

namespace {

// Top-level keys that hold no parameter of the dynamics.
constexpr const char* kSettings[] = {"name", "time", "solver", "output", "limits", "sensitivities"};

// The relative step of a difference quotient: the cube root of the machine epsilon balances
// a central quotient's truncation error (h^2) against rounding (eps / h).
constexpr double kRelativeStep = 6e-6;

// One build of the scenario: the network integrated and its initial state.
struct Built {
  std::shared_ptr<const NetworkSystem> system;
  std::vector<double> initial;
  const ActuatorSystem* actuator = nullptr;  // the single actuator's, else null
};

// Builds the scenario with overrides, either form.
class Builder {
 public:
  Builder(const std::string& path, std::vector<std::string> overrides)
      : network_(IsNetworkScenario(path)), overrides_(std::move(overrides)) {
    if (network_) {
      network_template_ = std::make_unique<NetworkScenarioTemplate>(path);
    } else {
      single_template_ = std::make_unique<ScenarioTemplate>(path);
    }
  }
  bool network() const { return network_; }

  // The scenario with one more override (none when `extra` is empty).
  Built Build(const std::string& extra) const {
    std::vector<std::string> overrides = overrides_;
    if (!extra.empty()) overrides.push_back(extra);
    Built built;
    if (network_) {
      const NetworkScenarioSpec spec = network_template_->Instantiate(overrides);
      auto system = std::make_shared<const NetworkSystem>(spec.Build());
      built.initial.resize(static_cast<std::size_t>(system->state_size()));
      system->InitialState(spec.t_start, built.initial.data());
      built.system = std::move(system);
      return built;
    }
    const ScenarioSpec spec = single_template_->Instantiate(overrides);
    auto actuator = std::make_shared<const ActuatorSystem>(BuildSystem(spec));
    built.initial = NetworkRequestOf(*actuator, spec.Request()).initial_state;
    built.actuator = actuator.get();
    built.system = std::shared_ptr<const NetworkSystem>(actuator, &actuator->network());
    return built;
  }

  ScenarioSpec SingleSpec() const { return single_template_->Instantiate(overrides_); }
  NetworkScenarioSpec NetworkSpec() const { return network_template_->Instantiate(overrides_); }

 private:
  bool network_;
  std::vector<std::string> overrides_;
  std::unique_ptr<ScenarioTemplate> single_template_;
  std::unique_ptr<NetworkScenarioTemplate> network_template_;
};

std::string ShortestText(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

// d/dp at `at` of the interpolating polynomial through `points`: weight_i of value_i.
std::vector<double> DerivativeWeights(const std::vector<double>& points, double at) {
  std::vector<double> weights(points.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    // L_i'(at) = sum over k != i of 1/(x_i - x_k) prod over m != i, k of (at - x_m)/(x_i - x_m)
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (k == i) continue;
      double term = 1.0 / (points[i] - points[k]);
      for (std::size_t m = 0; m < points.size(); ++m) {
        if (m != i && m != k) term *= (at - points[m]) / (points[i] - points[m]);
      }
      weights[i] += term;
    }
  }
  return weights;
}

// A parameter without a closed form: a difference quotient over the scenario rebuilt at
// nearby values, central where both sides are valid values, else one-sided of second order
// (a damping of 0 cannot go below it).
void AddDifferenceQuotient(const Builder& builder, const Built& base, const std::string& path,
                           double value, const std::string& where, SensitivitySetup& setup) {
  const double h = kRelativeStep * (value != 0.0 ? std::abs(value) : 1.0);
  struct Point {
    double value;
    std::optional<Built> built;
    std::string error;
  };
  const auto build_at = [&](double at) {
    const std::string text = ShortestText(at);
    Point point{std::strtod(text.c_str(), nullptr), std::nullopt, ""};
    try {
      point.built = builder.Build(path + "=" + text);
    } catch (const InputError& e) {
      point.error = e.what();
    }
    return point;
  };
  std::vector<Point> points;
  Point below = build_at(value - h);
  Point above = build_at(value + h);
  if (below.built && above.built) {
    points.push_back(std::move(below));
    points.push_back(std::move(above));
  } else if (above.built || below.built) {
    const double direction = above.built ? 1.0 : -1.0;
    Point near = above.built ? std::move(above) : std::move(below);
    Point far = build_at(value + 2.0 * direction * h);
    if (!far.built) {
      throw InputError(where + " = " + FormatNumber(value) +
                       ": no neighbourhood of valid values to differentiate in: " + far.error);
    }
    points.push_back(Point{value, base, ""});
    points.push_back(std::move(near));
    points.push_back(std::move(far));
  } else {
    throw InputError(where + " = " + FormatNumber(value) +
                     ": cannot change continuously (an integer, or a value at the edge of its "
                     "range on both sides), so it has no sensitivity; near it: " + below.error);
  }
  const NetworkRunRequest& request = setup.request;
  const std::vector<double> breakpoints =
      base.system->Breakpoints(request.t_start, request.t_end);
  std::vector<double> values;
  DifferenceQuotientDerivative::Stencil stencil;
  for (const Point& point : points) {
    const std::vector<double> moved =
        point.built->system->Breakpoints(request.t_start, request.t_end);
    if (moved != breakpoints || point.built->system->state_size() != base.system->state_size()) {
      throw InputError(where +
                       ": moves when an input jumps (a breakpoint of an activation, excitation, "
                       "load or motion): the sensitivity jumps there (docs/model.md 10), which "
                       "musclesim does not compute; differentiate by a value the times do not "
                       "depend on");
    }
    values.push_back(point.value);
  }
  const std::vector<double> weights = DerivativeWeights(values, value);
  std::vector<double> initial(base.initial.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    stencil.push_back({points[i].built->system, weights[i], points[i].value - value});
    for (std::size_t k = 0; k < initial.size(); ++k) {
      initial[k] += weights[i] * points[i].built->initial[k];
    }
  }
  setup.derivatives.push_back(std::make_unique<DifferenceQuotientDerivative>(std::move(stencil)));
  setup.sources.push_back(DerivativeSource::kDifferenceQuotient);
  setup.parameters.push_back({setup.derivatives.back().get(), std::move(initial), 1.0});
}

// A model block as built: its tension model, and whether its Gaussians are fitted at load
// (then a change of the active length's range or sigma refits them, which the closed form of
// a fixed sum does not see).
struct BuiltModel {
  const TensionModel* model = nullptr;
  bool fitted = false;
};

// The tension model a path's parameter belongs to, and the path within its block; no model
// when the closed form does not hold for it.
struct ModelPath {
  const TensionModel* model = nullptr;
  std::string relative;
};

ModelPath FindModelPath(const std::string& path, const std::map<std::string, BuiltModel>& models,
                        bool network) {
  std::string name, relative;
  if (!network) {
    if (path.rfind("model.", 0) != 0) return {};
    relative = path.substr(6);
  } else {
    if (path.rfind("models.", 0) != 0) return {};
    const std::size_t dot = path.find('.', 7);
    if (dot == std::string::npos) return {};
    name = path.substr(7, dot - 7);
    relative = path.substr(dot + 1);
  }
  const auto found = models.find(name);
  if (found == models.end()) return {};
  if (found->second.fitted && relative.rfind("active_length.", 0) == 0) return {};
  return {found->second.model, relative};
}

// `steps` written back in one spelling ("load[0].after" for "load[00]after"), so that one
// parameter has one column name.
std::string Canonical(const std::vector<yaml::KeyPathStep>& steps) {
  std::string path;
  for (const yaml::KeyPathStep& step : steps) {
    if (step.key.empty()) {
      path += "[" + std::to_string(step.index) + "]";
    } else {
      path += (path.empty() ? "" : ".") + step.key;
    }
  }
  return path;
}

// A column name must not break the CSV's header: no comma, quote or control character.
bool FitsCsvHeader(const std::string& path) {
  return std::none_of(path.begin(), path.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return c == ',' || c == '"' || byte < 0x20 || byte == 0x7f;
  });
}

}  // namespace

SensitivitySetup PrepareSensitivities(const std::string& path,
                                      const std::vector<std::string>& overrides,
                                      const std::vector<std::string>& parameters) {
  const Builder builder(path, overrides);
  SensitivitySetup setup;
  setup.source = path;
  std::vector<std::string> paths, where;
  for (const std::string& p : parameters) {
    paths.push_back(p);
    where.push_back("--sensitivity");
  }
  std::map<std::string, BuiltModel> models;
  Built base = builder.Build("");
  if (builder.network()) {
    const NetworkScenarioSpec spec = builder.NetworkSpec();
    setup.name = spec.name;
    setup.solver = spec.solver;
    setup.request = spec.Request();
    setup.output_file = spec.output.file;
    setup.phase_tolerance = spec.output.phase_tolerance;
    for (const auto& [name, model] : spec.tension_models) {
      models[name] = {model.get(), spec.models.at(name).fit.has_value()};
    }
    // the same models the base system's actuators hold, so a closed form finds them
    base.system = std::make_shared<const NetworkSystem>(spec.Build());
    paths.insert(paths.end(), spec.sensitivities.begin(), spec.sensitivities.end());
    for (std::size_t i = 0; i < spec.sensitivities_at.size(); ++i) {
      where.push_back(spec.sensitivities_at[i] + ": sensitivities[" + std::to_string(i) + "]");
    }
    if (!spec.controllers.empty() && !paths.empty()) {
      // the controllers' terms of the sensitivity equations (docs/model.md 10) are not derived
      throw InputError(where.front() + " " + paths.front() + ": sensitivities of a network "
                       "with controllers are not supported yet (" + path + " has controllers[0] " +
                       spec.controllers.front().name + "); run it without sensitivities");
    }
  } else {
    const ScenarioSpec spec = builder.SingleSpec();
    setup.name = spec.name;
    setup.solver = spec.solver;
    setup.request = NetworkRequestOf(*base.actuator, spec.Request());
    setup.output_file = spec.output.file;
    setup.phase_tolerance = spec.PhaseTolerance();
    models[""] = {&base.actuator->model(), spec.model.fit.has_value()};
    paths.insert(paths.end(), spec.sensitivities.begin(), spec.sensitivities.end());
    for (std::size_t i = 0; i < spec.sensitivities_at.size(); ++i) {
      where.push_back(spec.sensitivities_at[i] + ": sensitivities[" + std::to_string(i) + "]");
    }
  }
  setup.actuator = base.actuator != nullptr
                       ? std::shared_ptr<const ActuatorSystem>(base.system, base.actuator)
                       : nullptr;
  setup.system = base.system;

  // the document as run, to read each parameter's value from
  YAML::Node root = yaml::LoadFile(path);
  for (const std::string& text : overrides) yaml::ApplyOverride(root, text, path);

  for (std::size_t i = 0; i < paths.size(); ++i) {
    const auto steps = yaml::SplitKeyPath(paths[i]);
    if (!steps || steps->empty() || steps->front().key.empty() || !FitsCsvHeader(paths[i])) {
      // the path as given, cut short: it may be anything
      const std::string shown = paths[i].size() > 80 ? paths[i].substr(0, 80) + "..." : paths[i];
      throw InputError(where[i] + " '" + shown +
                       "': not a dotted key path such as model.f_iso or load[0].value (names "
                       "without commas, quotes or control characters, indices in brackets)");
    }
    const std::string p = Canonical(*steps);
    where[i] += " " + p;
    if (std::find(setup.paths.begin(), setup.paths.end(), p) != setup.paths.end()) continue;
    for (const char* setting : kSettings) {
      if (steps->front().key == setting) {
        throw InputError(where[i] + ": a setting of the run, not a parameter of its dynamics: it "
                         "has no sensitivity");
      }
    }
    const std::optional<std::string> text = yaml::ScalarAt(root, p);
    if (!text) {
      throw InputError(where[i] + ": no value in the scenario: a sensitivity needs a number "
                       "written in the file (or given with --set)");
    }
    char* end = nullptr;
    const double value = std::strtod(text->c_str(), &end);
    if (text->empty() || *end != '\0' || !std::isfinite(value)) {
      throw InputError(where[i] + " = " + *text + ": not a number: it has no sensitivity");
    }
    setup.paths.push_back(p);
    setup.values.push_back(value);
    const ModelPath model = FindModelPath(p, models, base.actuator == nullptr);
    std::unique_ptr<ParameterDerivative> closed_form =
        model.model != nullptr
            ? ModelParameterDerivative(*base.system, model.model, model.relative)
            : nullptr;
    // a network's spring, tendon or damper: elements[i].<key>
    if (closed_form == nullptr && base.actuator == nullptr && steps->size() >= 3 &&
        steps->front().key == "elements" && (*steps)[1].key.empty() &&
        (*steps)[1].index < base.system->elements().size()) {
      const std::string relative = p.substr(p.find(']') + 2);
      closed_form = ElementParameterDerivative(
          *base.system, static_cast<int>((*steps)[1].index), relative);
    }
    if (closed_form != nullptr) {
      setup.derivatives.push_back(std::move(closed_form));
      setup.sources.push_back(DerivativeSource::kAnalytic);
      // no model parameter moves the initial state
      setup.parameters.push_back(
          {setup.derivatives.back().get(), std::vector<double>(base.initial.size(), 0.0), 1.0});
    } else {
      AddDifferenceQuotient(builder, base, p, value, where[i], setup);
    }
    setup.parameters.back().scale = value != 0.0 ? std::abs(value) : 1.0;
  }
  return setup;
}

}  // namespace musclesim
