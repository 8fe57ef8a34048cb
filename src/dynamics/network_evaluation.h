// Private: a network evaluated (network.cc): its initial state, right-hand side, Jacobian,
// kinks, inputs' breaks and observations, on a line here and by
// dispatch to network_space.h in the plane and in space. NetworkSystem's methods of the same
// names (network.h) say what each computes.
#pragma once

#include <vector>

#include "musclesim/dynamics/network_model.h"
#include "musclesim/dynamics/network_sample.h"
#include "musclesim/dynamics/network_scratch.h"

namespace musclesim::network {

void InitialState(const NetworkModel& m, double t_start, double* y);
void CheckInitialState(const NetworkModel& m, double t, const double* y);
void RightHandSide(const NetworkModel& m, double t, const double* y, double* ydot,
                   NetworkScratch& scratch);
void Jacobian(const NetworkModel& m, double t, const double* y, double* values,
              NetworkScratch& scratch);
// The single free node's right-hand side (Anchored).
void SingleNodeRightHandSide(const NetworkModel& m, double t, const double* y, double* ydot);

double Length(const NetworkModel& m, int e, double t, const double* y);
double LengtheningRate(const NetworkModel& m, int e, double t, const double* y);
double KinkValue(const NetworkModel& m, const Kink& kink, double t, const double* y);
std::vector<double> Breakpoints(const NetworkModel& m, double t0, double t1);

void Observe(const NetworkModel& m, double t, const double* y, NetworkSample& sample);
void ObserveElement(const NetworkModel& m, int e, double t, const double* y, ElementSample& out);
double LoadOn(const NetworkModel& m, int i, double t, const double* y);

// An end's position and velocity on a line (a junction's velocity solved, network_junction.h).
double PositionOf(const NetworkModel& m, const End& end, double t, const double* y);
double VelocityOf(const NetworkModel& m, const End& end, double t, const double* y);
// An end's velocity, a junction's taken from `w` (JunctionVelocities).
inline double RateOf(const NetworkModel& m, const End& end, double t, const double* y,
                     const double* w) {
  return end.junction >= 0 ? w[end.junction] : VelocityOf(m, end, t, y);
}

}  // namespace musclesim::network
