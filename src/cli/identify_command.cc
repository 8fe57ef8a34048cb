// musclesim identify DATA.yaml [-o MODEL.yaml] [--report PATH]
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/errors.h"
#include "musclesim/io/identify_spec.h"
#include "musclesim/io/model_yaml_writer.h"
#include "musclesim/io/output_file.h"
#include "musclesim/studies/identify.h"
#include "musclesim/studies/identify_report.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim identify DATA.yaml [-o MODEL.yaml] [--report PATH]

Fits the model's parameters to measured curves and prints a complete `model:` block, each
parameter with its standard error and each curve's RMSE in comments, and the slack length's
95% profile-likelihood interval with the range of k_p and alpha across it (the slack length
can be weakly determined: see the README). DATA.yaml holds any of:
  passive:  {csv: passive.csv}                                columns length,tension
  active:   {csv: active.csv, count: 3, nonnegative: true}    columns length,tension
  velocity: {csv: velocity.csv, f_iso: 100}                   columns shortening_velocity,tension
(CSV paths relative to DATA.yaml; f_iso optional, held fixed when given.) Velocity data with
points v < 0 give the eccentric branch too (v_max, n and a limit under `eccentric:`), the
concentric one then coming from v >= 0; what the data cannot determine is said so and left out.
  -o PATH         write the model block there (atomically) instead of standard output
  --report PATH   also write a Markdown report comparing each fit with a natural cubic spline
                  and polynomials of degree 3 and 4 (RMSE, leave-one-out RMSE, behaviour outside
                  the data, ns per evaluation), and the passive notes of the model block
Exit codes: 0 success, 2 invalid input or data, 1 anything else.
)";

std::string PlusMinus(const Estimate& e) {
  return FormatNumber(e.value) + " +- " +
         (std::isfinite(e.standard_error) ? FormatNumber(e.standard_error) : "n/a");
}

// The model block: each part identified, with its standard errors, or left to its stand-in
// with the reason.
ModelYamlDraft DraftModel(const IdentifySpec& spec,
                          const std::optional<PassiveIdentification>& passive,
                          const std::optional<ActiveIdentification>& active,
                          const std::optional<VelocityIdentification>& velocity) {
  ModelYamlDraft draft;
  draft.header = {"identified by musclesim identify from " + spec.source,
                  "(+- standard errors from the Jacobian at the optimum)"};
  if (active) {
    draft.f_iso = {active->f_iso.value,
                   {"N, " + PlusMinus(active->f_iso) + ", the active curve's maximum"}};
  } else if (velocity) {
    draft.f_iso = {velocity->best.f_iso.value,
                   {"N, " + PlusMinus(velocity->best.f_iso) + ", from the tension-velocity curve"}};
  } else {
    draft.f_iso.comments = {"not identified (no active or velocity data)"};
  }

  if (passive) {
    draft.passive.params =
        PassiveParams{passive->k_p.value, passive->alpha.value, passive->slack_length.value};
    draft.passive.comments = {"k_p = " + PlusMinus(passive->k_p) + " N, alpha = " +
                              PlusMinus(passive->alpha) + " 1/m, slack_length = " +
                              PlusMinus(passive->slack_length) + " m; RMSE " +
                              FormatNumber(passive->rmse) + " N"};
    for (const std::string& note : PassiveUncertaintyNotes(*passive, FormatNumber)) {
      draft.passive.comments.push_back(note);
    }
  } else {
    draft.passive.comments = {"not identified: no passive tension"};
  }

  if (active) {
    draft.active_length.params = active->curve;
    draft.active_length.comments = {
        "optimal_range: where the fitted curve is within 2% of its maximum; RMSE " +
        FormatNumber(active->rmse) + " N"};
    for (std::size_t k = 0; k < active->curve.gaussians.size(); ++k) {
      draft.gaussian_comments.push_back(
          "amplitude " + PlusMinus(active->amplitudes[k]) + ", width " +
          PlusMinus(active->precisions[k]) + ", center " + PlusMinus(active->centers[k]));
    }
  } else {
    draft.active_length.comments = {"not identified: one Gaussian a kilometre wide, a flat f_L"};
  }

  if (velocity) {
    const VelocityCandidate& best = velocity->best;
    VelocityParams params{best.v_max.value, best.n, StandInEpsilon(best.v_max.value)};
    std::string others = "other n:";
    for (const VelocityCandidate& c : velocity->candidates) {
      if (c.n == best.n) continue;
      others += " n=" + std::to_string(c.n) + " " +
                (c.valid ? "RMSE " + FormatNumber(c.rmse) : "no fit") + ";";
    }
    std::vector<std::string> eccentric_comments;
    std::string epsilon_rule = "1e-3 v_max";
    if (velocity->eccentric) {
      const EccentricIdentification& e = *velocity->eccentric;
      eccentric_comments = DescribeEccentric(e);
      if (e.identified) {
        params.eccentric = {e.best.v_max.value, e.best.n, std::nullopt};
        if (e.limit_identified) params.eccentric.limit = e.best.limit.value;
        // eps must not exceed either v_max (the model's rule)
        if (e.best.v_max.value < best.v_max.value) {
          params.epsilon = StandInEpsilon(e.best.v_max.value);
          epsilon_rule = "1e-3 times the eccentric v_max, the smaller";
        }
        std::string other_exponents = "other eccentric n:";
        for (const EccentricCandidate& c : e.limit_identified ? e.bounded : e.unbounded) {
          if (c.n == e.best.n) continue;
          other_exponents += " n=" + std::to_string(c.n) + " " +
                             (c.valid ? "RMSE " + FormatNumber(c.rmse) : "no fit") + ";";
        }
        eccentric_comments.push_back(other_exponents);
      }
    }
    try {
      Validate(params);  // extreme eccentric estimates may break the model's rules: say so
    } catch (const ParameterError& error) {
      params.eccentric = {};
      params.epsilon = StandInEpsilon(best.v_max.value);
      epsilon_rule = "1e-3 v_max";
      eccentric_comments.push_back("eccentric branch left out: it gives velocity." + error.path() +
                                   " = " + error.value() + ", which " + error.rule());
    }
    draft.velocity.params = params;
    draft.velocity.comments = {"v_max = " + PlusMinus(best.v_max) + " m/s, RMSE " +
                                   FormatNumber(best.rmse) + " N; epsilon is not identified (" +
                                   epsilon_rule + ")",
                               others};
    draft.velocity.comments.insert(draft.velocity.comments.end(), eccentric_comments.begin(),
                                   eccentric_comments.end());
  } else {
    draft.velocity.comments = {"not identified: g close to 1"};
  }
  return draft;
}

// Runs `step` on the curve of `spec`'s block `key` (its CSV `csv`, named at `at`): an input
// error in that data says which entry of which data file led to it.
template <typename Step>
auto InData(const std::string& key, const std::string& csv, const std::string& at, Step step) {
  try {
    return step();
  } catch (const InputError& e) {
    throw InputError(key + ".csv = " + csv + " (" + at + "): " + e.what());
  }
}

}  // namespace

int IdentifyCommand(int argc, char** argv) {
  if (NamesSeriesDataFile(argc, argv)) return IdentifySeriesCommand(argc, argv);
  const Arguments args = Parse(argc, argv, 2, {"-o", "--report"}, {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp << IdentifySeriesHelp();
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("expected one data file (see --help)");
  const IdentifySpec spec = LoadIdentifySpec(args.positional[0]);

  std::optional<PassiveIdentification> passive;
  std::optional<ActiveIdentification> active;
  std::optional<VelocityIdentification> velocity;
  std::vector<CurveComparison> comparisons;
  const bool report = args.Has("--report");
  if (spec.passive_csv) {
    const auto data = InData("passive", *spec.passive_csv, spec.passive_csv_at,
                             [&] { return ReadCurveCsv(*spec.passive_csv, "length", "tension", 4); });
    passive = InData("passive", *spec.passive_csv, spec.passive_csv_at,
                     [&] { return IdentifyPassive(data); });
    if (report) {
      auto models = ReferenceFitters();
      models.insert(models.begin(), {"exponential (eq. 1)", [](const std::vector<DataPoint>& d) {
        const PassiveIdentification fit = IdentifyPassive(d);
        return std::function<double(double)>([fit](double x) { return fit.Evaluate(x); });
      }});
      comparisons.push_back(Compare("passive tension-length", "length units of the CSV", data, models));
      comparisons.back().notes = PassiveUncertaintyNotes(*passive, [](double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%.4g", x);
        return std::string(text);
      });
    }
  }
  if (spec.active_csv) {
    const auto data = InData("active", *spec.active_csv, spec.active_csv_at, [&] {
      return ReadCurveCsv(*spec.active_csv, "length", "tension",
                          3 * static_cast<std::size_t>(spec.active_count) + 1);
    });
    active = InData("active", *spec.active_csv, spec.active_csv_at, [&] {
      return IdentifyActive(data, spec.active_count, spec.active_nonnegative);
    });
    if (report) {
      auto models = ReferenceFitters();
      const int count = spec.active_count;
      const bool nonnegative = spec.active_nonnegative;
      models.insert(models.begin(), {std::to_string(count) + " Gaussians (eqs. 3-4)",
                                     [count, nonnegative](const std::vector<DataPoint>& d) {
        const ActiveIdentification fit = IdentifyActive(d, count, nonnegative);
        return std::function<double(double)>([fit](double x) { return fit.Evaluate(x); });
      }});
      comparisons.push_back(Compare("active tension-length", "length units of the CSV", data, models));
    }
  }
  if (spec.velocity_csv) {
    const auto data = InData("velocity", *spec.velocity_csv, spec.velocity_csv_at, [&] {
      return ReadCurveCsv(*spec.velocity_csv, "shortening_velocity", "tension",
                          spec.velocity_f_iso ? 2 : 3);
    });
    velocity = InData("velocity", *spec.velocity_csv, spec.velocity_csv_at,
                      [&] { return IdentifyVelocity(data, spec.velocity_f_iso); });
    if (report) {
      auto models = ReferenceFitters();
      const std::optional<double> f_iso = spec.velocity_f_iso;
      models.insert(models.begin(), {"power law (eq. 12)", [f_iso](const std::vector<DataPoint>& d) {
        const VelocityIdentification fit = IdentifyVelocity(d, f_iso);
        return std::function<double(double)>([fit](double v) { return fit.Evaluate(v); });
      }});
      comparisons.push_back(Compare("tension-velocity", "shortening velocity units of the CSV", data, models));
      if (velocity->eccentric) comparisons.back().notes = DescribeEccentric(*velocity->eccentric);
    }
  }

  WriteOutput(args.Value("-o", "-"),
              FormatModelYaml(DraftModel(spec, passive, active, velocity)));
  if (report) WriteOutput(args.Value("--report"), FormatReport(comparisons));
  return kExitSuccess;
}

}  // namespace musclesim::cli
