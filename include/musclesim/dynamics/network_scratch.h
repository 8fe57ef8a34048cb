// What evaluating a network writes besides its results: the working buffers of its
// right-hand side, Jacobian and parameter derivatives. A NetworkSystem is the immutable
// model, shared by every thread that integrates it; each integration (a session, a stepper,
// a recorder) owns one scratch and passes it to every evaluation. The buffers grow on first
// use and are reused after, so evaluation allocates nothing past its first call, and a
// scratch default-constructed fits any network.
#pragma once

#include <vector>

#include "musclesim/dynamics/network_sample.h"

namespace musclesim {

struct NetworkScratch {
  std::vector<double> junction_velocities;   // w of every massless junction [m/s]
  std::vector<double> junction_rate_slopes;  // per element at one junction: dT/d(ldot) [N s/m]
  std::vector<double> rate;                  // one right-hand side (a difference quotient's)
  std::vector<double> rate_minus;            // another (a central difference's)
  std::vector<double> shifted;               // a state moved along a direction
  NetworkSample sample;                      // one observation
};

}  // namespace musclesim
