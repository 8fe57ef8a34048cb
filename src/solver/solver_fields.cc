// The solver's options: their names (one table per enum) and their description.
#include "musclesim/solver/solver_fields.h"

#include <limits>

#include "musclesim/core/enum_names.h"

namespace musclesim {

namespace {

constexpr EnumName<IntegrationMethod> kMethodNames[] = {
    {IntegrationMethod::kBdf, "bdf"},
    {IntegrationMethod::kAdams, "adams"},
};

constexpr EnumName<JacobianKind> kJacobianNames[] = {
    {JacobianKind::kAnalytic, "analytic"},
    {JacobianKind::kDifferenceQuotient, "difference_quotient"},
};

constexpr EnumName<LinearSolverKind> kLinearSolverNames[] = {
    {LinearSolverKind::kDense, "dense"},   {LinearSolverKind::kBand, "band"},
    {LinearSolverKind::kSparse, "sparse"}, {LinearSolverKind::kAuto, "auto"},
    {LinearSolverKind::kSmall, "small"},
};

// below ~100 roundoffs double precision cannot meet a tolerance (CVODE: CV_TOO_MUCH_ACC); at 1
// the error allowed is as large as the value itself
constexpr InputRange kRelativeToleranceRange{
    kMinTolerance,
    1.0,
    "-",
    "below 1e-14 (about 100 roundoffs) double precision cannot meet it, and at 1 the error "
    "allowed is as large as the value",
    false,
    true};
constexpr InputRange kAbsoluteToleranceRange{
    0.0,
    1.0,
    "m and m/s",
    "an absolute error of a metre or a metre per second says nothing about an actuator",
    true,
    true};
constexpr InputRange kMaxStepRange{
    0.0, std::numeric_limits<double>::max(), "s",
    "0 is no limit; any finite step is accepted, and one longer than the run limits nothing"};
constexpr InputRange kMaxStepsRange{1.0, 1e12, "-", "a guard on the internal steps of one run"};

PartVariant<SolverOptions> Describe() {
  using O = SolverOptions;
  const O defaults;
  NumberField<O> max_steps{"max_steps",
                           kMaxStepsRange,
                           static_cast<double>(defaults.max_steps),
                           "the internal steps one run may take before it fails (CV_TOO_MUCH_WORK)",
                           [](const O& o) { return static_cast<double>(o.max_steps); },
                           [](O& o, double v) { o.max_steps = static_cast<long>(v); }};
  max_steps.integer = true;
  PartVariant<O> block =
      OnlyVariant<O>("solver", "CVODES",
                     {MemberField("rtol", &O::rtol, kRelativeToleranceRange, defaults.rtol,
                                  "the relative tolerance of the local error test"),
                      MemberField("atol", &O::atol, kAbsoluteToleranceRange, defaults.atol,
                                  "the absolute tolerance on positions and velocities"),
                      MemberField("max_step", &O::max_step, kMaxStepRange, defaults.max_step,
                                  "the largest internal step (0: no limit)"),
                      std::move(max_steps)});
  block.words = {
      EnumField("method", &O::method, kMethodNames,
                "the integration method: bdf (stiff problems: the default) or adams (nonstiff)"),
      EnumField("jacobian", &O::jacobian, kJacobianNames,
                "the Newton iteration's Jacobian: the analytic one, or a difference quotient"),
      EnumField("linear_solver", &O::linear_solver, kLinearSolverNames,
                "how the Newton systems are solved: auto picks small, band or sparse by the "
                "system's size and structure (docs/solver.md)"),
  };
  return block;
}

}  // namespace

std::string_view ToString(IntegrationMethod method) { return ToString(kMethodNames, method); }

IntegrationMethod ParseIntegrationMethod(std::string_view text) {
  return Parse(kMethodNames, "method", text);
}

std::string_view ToString(JacobianKind kind) { return ToString(kJacobianNames, kind); }

JacobianKind ParseJacobianKind(std::string_view text) {
  return Parse(kJacobianNames, "jacobian", text);
}

std::string_view ToString(LinearSolverKind kind) { return ToString(kLinearSolverNames, kind); }

LinearSolverKind ParseLinearSolverKind(std::string_view text) {
  return Parse(kLinearSolverNames, "linear_solver", text);
}

const std::vector<PartVariant<SolverOptions>>& SolverBlock() {
  static const std::vector<PartVariant<SolverOptions>> block{Describe()};
  return block;
}

void Validate(const SolverOptions& options) { ValidateFields(SolverBlock().front(), options); }

}  // namespace musclesim
