#include "musclesim/optimize/problem_fields.h"

#include <limits>
#include <string>
#include <utility>

#include "musclesim/core/input_ranges.h"
#include "musclesim/io/writers/reference_table.h"

namespace musclesim {

namespace {

constexpr InputRange kIntervalRange{1.0, 100000.0, "-",
                                    "each interval is a shooting segment: 1e5 of them is "
                                    "beyond any problem IPOPT solves in a working day"};
constexpr InputRange kWeightRange{0.0, 1e12, "-",
                                  "a weight of the objective: >= 0, and within 1e12 of the "
                                  "other terms, which IPOPT's scaling can still resolve"};
constexpr InputRange kPowerRange{2.0, 3.0, "-", "2: integral of u^2; 3: integral of |u|^3"};
constexpr InputRange kColumnValueRange{-1e12, 1e12, "the column's unit",
                                       "beyond 1e12 no quantity of a run lies"};
constexpr InputRange kParameterValueRange{-1e12, 1e12, "the parameter's unit",
                                          "beyond 1e12 no number of a scenario lies"};
constexpr InputRange kFinalValueRange{-1e6, 1e6, "the column's unit",
                                      "a coordinate [m] or velocity [m/s] of the final state"};
constexpr InputRange kFinalTimeRange{-1e9, 1e9, "s", "a time of the run"};
constexpr InputRange kToleranceRange{1e-14, 1.0, "-",
                                     "IPOPT's tol, of the scaled optimality error: below 1e-14 "
                                     "double precision cannot meet it"};
constexpr InputRange kIterationRange{1.0, 100000.0, "-", "IPOPT's max_iter"};
constexpr InputRange kSecondsRange{0.0, 1e7, "s",
                                   "the solve's wall time, checked after each iteration", true};

// The field of the double `member` of a Part.
template <typename Part>
NumberField<Part> Number(const char* key, double Part::*member, const InputRange& range,
                         std::optional<double> fallback, const char* doc) {
  return MemberField(key, member, range, fallback, doc);
}

// The field of the int `member`: a whole number within `range`.
template <typename Part>
NumberField<Part> Whole(const char* key, int Part::*member, const InputRange& range,
                        std::optional<double> fallback, const char* doc) {
  NumberField<Part> field{key,
                          range,
                          fallback,
                          doc,
                          [member](const Part& p) { return static_cast<double>(p.*member); },
                          [member](Part& p, double v) { p.*member = static_cast<int>(v); }};
  field.integer = true;
  return field;
}

// A text of a part, `member`, required unless said otherwise.
template <typename Part>
TextField<Part> Text(const char* key, std::string Part::*member, const char* doc,
                     bool required = true) {
  return {key, doc, [member](const Part& p) { return p.*member; },
          [member](Part& p, std::string v) { p.*member = std::move(v); }, required};
}

template <typename Part>
PartVariant<Part> Entry(const char* type, const char* law, std::vector<NumberField<Part>> fields,
                        std::vector<TextField<Part>> texts) {
  PartVariant<Part> entry = OnlyVariant<Part>(type, law, std::move(fields));
  entry.texts = std::move(texts);
  return entry;
}

}  // namespace

const std::vector<PartVariant<ProblemFile>>& ProblemKeys() {
  static const std::vector<PartVariant<ProblemFile>> keys = [] {
    NumberField<ProblemFile> intervals{
        "intervals",
        kIntervalRange,
        20.0,
        "N: the control grid has N + 1 points, evenly spaced over the span",
        [](const ProblemFile& f) { return static_cast<double>(f.problem.intervals); },
        [](ProblemFile& f, double n) { f.problem.intervals = static_cast<int>(n); }};
    intervals.integer = true;
    PartVariant<ProblemFile> problem = Entry<ProblemFile>(
        "problem", "the controls (and parameters) minimising the objective under the constraints",
        {std::move(intervals)},
        {Text("base", &ProblemFile::base,
              "the base scenario, relative to the problem file (a file's only)")});
    problem.other_keys = {"controls",   "final_values", "path_bounds", "tracking", "terminal",
                          "parameters", "final_time",   "optimizer",   "output"};
    return std::vector{std::move(problem)};
  }();
  return keys;
}

const std::vector<PartVariant<ControlSpec>>& ControlEntry() {
  using C = ControlSpec;
  static const std::vector<PartVariant<C>> entry{Entry<C>(
      "controls[k]", "u(t), piecewise linear on the grid",
      {Number("bounds[0]", &C::lower, kActivationRange, 0.0, "its lowest value at every point"),
       Number("bounds[1]", &C::upper, kActivationRange, 1.0, "its highest, at least bounds[0]"),
       Number("effort.weight", &C::effort_weight, kWeightRange, 1.0,
              "w of the effort term w * integral of u^q dt"),
       Whole("effort.power", &C::effort_power, kPowerRange, 2.0, "q of the effort term")},
      {Text("actuator", &C::actuator,
            "the actuator it drives: one without activation dynamics or a controller")})};
  return entry;
}

const std::vector<PartVariant<FinalValue>>& FinalValueEntry() {
  using F = FinalValue;
  static const std::vector<PartVariant<F>> entry = [] {
    NumberField<F> value{"value",
                         kFinalValueRange,
                         std::nullopt,
                         "the column's value at the final time: an equality; or bounds",
                         [](const F& f) { return f.lower; },
                         [](F& f, double v) { f.lower = f.upper = v; }};
    NumberField<F> lower = Number("bounds[0]", &F::lower, kFinalValueRange, std::nullopt,
                                  "its lowest value at the final time; or value");
    NumberField<F> upper = Number("bounds[1]", &F::upper, kFinalValueRange, std::nullopt,
                                  "its highest, at least bounds[0]");
    // one of the two, the reader's rule: each optional alone
    for (NumberField<F>* field : {&value, &lower, &upper}) {
      field->given = [](const F&) { return true; };
    }
    return std::vector{
        Entry<F>("final_values[k]", "a bound on a column at the final time",
                 {std::move(value), std::move(lower), std::move(upper)},
                 {Text("column", &F::column, "the column, as the run's CSV names it")})};
  }();
  return entry;
}

const std::vector<PartVariant<PathBound>>& PathBoundEntry() {
  using B = PathBound;
  static const std::vector<PartVariant<B>> entry{
      Entry<B>("path_bounds[k]", "a bound on a column at every grid point after the start",
               {Number("bounds[0]", &B::lower, kColumnValueRange, std::nullopt, "its lowest value"),
                Number("bounds[1]", &B::upper, kColumnValueRange, std::nullopt,
                       "its highest, at least bounds[0]")},
               {Text("column", &B::column, "the column, as the run's CSV names it")})};
  return entry;
}

const std::vector<PartVariant<TrackingTerm>>& TrackingEntry() {
  using T = TrackingTerm;
  static const std::vector<PartVariant<T>> entry = [] {
    PartVariant<T> term =
        Entry<T>("tracking[k]", "w * integral of (column(t) - r(t))^2 dt",
                 {Number("weight", &T::weight, kWeightRange, 1.0, "w")},
                 {Text("column", &T::column, "the column, as the run's CSV names it")});
    term.other_keys = {"reference"};
    return std::vector{std::move(term)};
  }();
  return entry;
}

const std::vector<PartVariant<TerminalTerm>>& TerminalEntry() {
  using T = TerminalTerm;
  static const std::vector<PartVariant<T>> entry{Entry<T>(
      "terminal[k]", "w * (column(t_end) - target)^2",
      {Number("target", &T::target, kColumnValueRange, std::nullopt, "the column's target"),
       Number("weight", &T::weight, kWeightRange, 1.0, "w")},
      {Text("column", &T::column, "the column, as the run's CSV names it")})};
  return entry;
}

const std::vector<PartVariant<FreeParameter>>& ParameterEntry() {
  using P = FreeParameter;
  static const std::vector<PartVariant<P>> entry{Entry<P>(
      "parameters[k]", "a number of the scenario chosen with the controls",
      {Number("bounds[0]", &P::lower, kParameterValueRange, std::nullopt, "its lowest value"),
       Number("bounds[1]", &P::upper, kParameterValueRange, std::nullopt,
              "its highest, at least bounds[0]")},
      {Text("path", &P::path, "its key path, as --set takes it")})};
  return entry;
}

const std::vector<PartVariant<FreeFinalTime>>& FinalTimeBlock() {
  using T = FreeFinalTime;
  static const std::vector<PartVariant<T>> block{
      Entry<T>("final_time", "t_end a variable, weight * t_end in the objective",
               {Number("bounds[0]", &T::lower, kFinalTimeRange, std::nullopt,
                       "its lowest value, after time.start"),
                Number("bounds[1]", &T::upper, kFinalTimeRange, std::nullopt,
                       "its highest, at least bounds[0]"),
                Number("weight", &T::weight, kWeightRange, 0.0, "weight: > 0 for a minimum time")},
               {})};
  return block;
}

const std::vector<PartVariant<OptimizeOptions>>& OptimizerBlock() {
  using O = OptimizeOptions;
  static const std::vector<PartVariant<O>> block = [] {
    PartVariant<O> optimizer =
        Entry<O>("optimizer", "IPOPT's settings",
                 {Number("tolerance", &O::tolerance, kToleranceRange, 1e-8, "IPOPT's tol"),
                  Whole("max_iterations", &O::max_iterations, kIterationRange, O{}.max_iterations,
                        "IPOPT's max_iter"),
                  Number("max_seconds", &O::max_seconds, kSecondsRange,
                         std::numeric_limits<double>::infinity(),
                         "the solve's wall time limit; none by default")},
                 {});
    optimizer.words = {EnumField("derivatives", &O::derivatives, kShootingDerivativesNames,
                                 "sensitivities: exact, by the forward sensitivities; "
                                 "difference_quotients: by differences")};
    return std::vector{std::move(optimizer)};
  }();
  return block;
}

const std::vector<PartVariant<OptimizeOutputs>>& ProblemOutputBlock() {
  using O = OptimizeOutputs;
  static const std::vector<PartVariant<O>> block{Entry<O>(
      "output", "what a solve writes (a file's only), each relative to the working directory", {},
      {Text("scenario", &O::scenario,
            "the base with the optimal controls as tables; <stem>_optimum.yaml by default", false),
       Text("summary", &O::summary,
            "JSON: status, objective, violation, iterations; <stem>_optimum.json by default",
            false),
       Text("trajectory", &O::trajectory,
            "CSV: the re-simulated optimum; <stem>_optimum.csv by default", false)})};
  return block;
}

std::string ProblemReference() {
  // the file's lists and blocks: the entries and blocks whose rows follow
  const auto list = [](const char* key, const char* required, const char* doc) {
    return std::pair<std::string, std::string>{
        key, std::string("| ") + required + " | a list of `" + key + "[k]` (below) | " + doc};
  };
  const auto block = [](const char* key, const char* doc) {
    return std::pair<std::string, std::string>{
        key, std::string("| optional | the block `") + key + "` (below) | " + doc};
  };
  const std::vector<std::pair<std::string, std::string>> cells{
      list("controls", "required", "the actuators whose inputs are chosen; at least one"),
      list("final_values", "optional", "bounds on columns at the final time"),
      list("path_bounds", "optional", "bounds on columns at every grid point"),
      list("tracking", "optional", "terms following a reference"),
      list("terminal", "optional", "terms reaching a target at the end"),
      list("parameters", "optional", "numbers of the scenario chosen too"),
      block("final_time", "the final time free"),
      block("optimizer", "IPOPT's settings"),
      block("output", "the files written")};
  return ReferenceHeader("entry") + ReferenceRows(ProblemKeys(), cells) +
         ReferenceRows(ControlEntry()) + ReferenceRows(FinalValueEntry()) +
         ReferenceRows(PathBoundEntry()) + ReferenceRows(TrackingEntry()) +
         ReferenceRows(TerminalEntry()) + ReferenceRows(ParameterEntry()) +
         ReferenceRows(FinalTimeBlock()) + ReferenceRows(OptimizerBlock()) +
         ReferenceRows(ProblemOutputBlock());
}

}  // namespace musclesim
