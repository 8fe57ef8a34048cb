// Standard normal draws for seeded noisy data sets: Box-Muller on std::mt19937_64, so the
// same numbers come out with every standard library (std::normal_distribution's algorithm
// is the library's choice).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace musclesim::testing {

class Noise {
 public:
  explicit Noise(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    const double u1 = (static_cast<double>(rng_() >> 11) + 0.5) * 0x1.0p-53;
    const double u2 = static_cast<double>(rng_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 rng_;
};

}  // namespace musclesim::testing
