// The interpolant of CVODE's last step as a polynomial in t - t_n, for a fine output grid:
// CVodeGetDky costs about as much per call as a few vector operations, and a step at a loose
// tolerance can hold dozens of output times. Fetching the q + 1 derivatives at t_n once and
// evaluating the Taylor polynomial at each output gives CVODE's own interpolant (its Nordsieck
// history is exactly these scaled derivatives) for the price of q + 1 calls.
#pragma once

#include <cvodes/cvodes.h>
#include <sundials/sundials_nvector.h>

#include <vector>

namespace musclesim {

class StepPolynomial {
 public:
  // Fetches the derivatives of the last step's interpolant at its end t_n into `scratch`'s
  // array, one at a time. Returns false if CVODE cannot give them (the caller interpolates
  // point by point instead).
  bool Fetch(void* cvode, N_Vector scratch, int size) {
    int order = 0;
    if (CVodeGetLastOrder(cvode, &order) < 0 || CVodeGetCurrentTime(cvode, &t_n_) < 0) {
      return false;
    }
    size_ = size;
    terms_ = order + 1;
    coefficients_.resize(static_cast<std::size_t>(terms_ * size));
    const double* values = N_VGetArrayPointer(scratch);
    double factorial = 1.0;
    for (int k = 0; k < terms_; ++k) {
      if (k > 0) factorial *= k;
      if (CVodeGetDky(cvode, t_n_, k, scratch) < 0) return false;
      for (int i = 0; i < size; ++i) {
        coefficients_[static_cast<std::size_t>(k * size + i)] = values[i] / factorial;
      }
    }
    return true;
  }

  int terms() const { return terms_; }

  // The interpolant at t (within the step) into out[0..size).
  void Evaluate(double t, double* out) const {
    const double s = t - t_n_;
    for (int i = 0; i < size_; ++i) {
      double value = coefficients_[static_cast<std::size_t>((terms_ - 1) * size_ + i)];
      for (int k = terms_ - 2; k >= 0; --k) {
        value = value * s + coefficients_[static_cast<std::size_t>(k * size_ + i)];
      }
      out[i] = value;
    }
  }

 private:
  double t_n_ = 0.0;
  int size_ = 0;
  int terms_ = 0;
  std::vector<double> coefficients_;  // term k of state i at k * size + i
};

}  // namespace musclesim
