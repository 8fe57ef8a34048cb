// Active identification: a sum of Gaussians by the closed-form samples fit; f_iso its maximum.
#include "musclesim/identify/identify.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

#include "musclesim/core/errors.h"
#include "musclesim/model/gaussian_fit.h"
#include "identify/identify_fit_statistics.h"

namespace musclesim {

using identify_detail::Covariance;
using identify_detail::Rmse;

namespace {

// The residual Jacobian of the fit of data / top by `gaussians` (their sum `sum`, sigma 1)
// in (a, b, d), for the standard errors; `rss` gets the residuals' sum of squares.
Eigen::MatrixXd NormalisedFitJacobian(const std::vector<DataPoint>& data,
                                      const std::vector<Gaussian>& gaussians, double top,
                                      const GaussianSum& sum, double& rss) {
  const auto m = static_cast<Eigen::Index>(gaussians.size());
  Eigen::MatrixXd jacobian(static_cast<Eigen::Index>(data.size()), 3 * m);
  rss = 0.0;
  for (std::size_t s = 0; s < data.size(); ++s) {
    const auto row = static_cast<Eigen::Index>(s);
    rss += std::pow(sum.Value(data[s].x) - data[s].y / top, 2);
    for (Eigen::Index k = 0; k < m; ++k) {
      const Gaussian& g = gaussians[static_cast<std::size_t>(k)];
      const double dx = data[s].x - g.center;
      // psi_k = a_k phi_k with sigma = 1: d/da = phi, d/db = -psi dx^2 / 2, d/dd = psi b dx
      const double phi = GaussianTerm::Unit(g.precision, g.center, 1.0)(data[s].x);
      jacobian(row, k) = phi;
      jacobian(row, m + k) = g.amplitude * phi * (-dx * dx / 2.0);
      jacobian(row, 2 * m + k) = g.amplitude * phi * g.precision * dx;
    }
  }
  return jacobian;
}

}  // namespace

ActiveIdentification IdentifyActive(const std::vector<DataPoint>& data, int count,
                                    bool nonnegative) {
  double top = 0.0;
  for (const DataPoint& d : data) top = std::max(top, std::abs(d.y));
  FitSpec spec;
  spec.count = count;
  spec.target = FitTargetKind::kSamples;
  spec.nonnegative = nonnegative;
  for (const DataPoint& d : data) spec.points.push_back({d.x, d.y / top});  // of order one
  FitResult fit;
  try {
    fit = FitGaussians(spec, data.front().x, data.back().x, 1.0);
  } catch (const ParameterError& e) {
    throw InputError("active data: " + std::string(e.what()));
  }
  const GaussianSum sum(fit.gaussians, 1.0);
  const Maximum peak = MaximumOnInterval(sum, data.front().x, data.back().x);
  if (!(peak.value > 0.0)) throw InputError("active data: the fitted curve is nowhere positive");

  ActiveIdentification out;
  out.f_iso.value = peak.value * top;
  out.curve.sigma = 1.0;
  for (Gaussian g : fit.gaussians) {
    g.amplitude /= peak.value;  // so that max f = 1
    out.curve.gaussians.push_back(g);
  }
  // optimal_range: where the fitted curve stays within 2% of its maximum
  const double span = data.back().x - data.front().x, step = span / 4000.0;
  double l1 = peak.x, l2 = peak.x;
  while (l1 - step >= data.front().x && sum.Value(l1 - step) >= 0.98 * peak.value) l1 -= step;
  while (l2 + step <= data.back().x && sum.Value(l2 + step) >= 0.98 * peak.value) l2 += step;
  if (!(l2 > l1)) {
    l1 = peak.x - 1e-6 * span;
    l2 = peak.x + 1e-6 * span;
  }
  out.curve.optimal_min = l1;
  out.curve.optimal_max = l2;
  out.sum = GaussianSum(out.curve.gaussians, out.curve.sigma);

  const auto m = static_cast<Eigen::Index>(fit.gaussians.size());
  double rss = 0.0;  // (set before the covariance reads it)
  const Eigen::MatrixXd jacobian = NormalisedFitJacobian(data, fit.gaussians, top, sum, rss);
  const Eigen::MatrixXd cov = Covariance(jacobian, rss);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Gaussian& g = out.curve.gaussians[static_cast<std::size_t>(k)];
    out.amplitudes.push_back({g.amplitude, std::sqrt(cov(k, k)) / peak.value});
    out.precisions.push_back({g.precision, std::sqrt(cov(m + k, m + k))});
    out.centers.push_back({g.center, std::sqrt(cov(2 * m + k, 2 * m + k))});
  }
  // f_iso's error by the delta method, its gradient by central differences of the peak
  Eigen::VectorXd gradient(3 * m);
  for (Eigen::Index j = 0; j < 3 * m; ++j) {
    const auto shifted = [&](double sign) {
      std::vector<Gaussian> gs = fit.gaussians;
      Gaussian& g = gs[static_cast<std::size_t>(j % m)];
      double& value = j < m ? g.amplitude : (j < 2 * m ? g.precision : g.center);
      const double h = 1e-6 * std::max(std::abs(value), j < 2 * m ? 1e-12 : span);
      value += sign * h;
      return std::make_pair(
          MaximumOnInterval(GaussianSum(gs, 1.0), data.front().x, data.back().x).value, h);
    };
    const auto [up, h] = shifted(1.0);
    const auto [down, h2] = shifted(-1.0);
    (void)h2;
    gradient(j) = top * (up - down) / (2.0 * h);
  }
  out.f_iso.standard_error = std::sqrt(gradient.dot(cov * gradient));
  out.rmse = Rmse(rss, data.size()) * top;
  return out;
}

}  // namespace musclesim
