// Private: a network in the plane or in space (docs/model.md 12): its paths built, measured
// and differentiated (network_space.cc, space_jacobian.cc).
#pragma once

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "dynamics/element_path.h"
#include "musclesim/dynamics/network_model.h"
#include "musclesim/dynamics/network_sample.h"

namespace musclesim::network {

// An element's path at one instant: its points' positions and velocities, measured.
// Over a wrap surface the path has two points more, where it touches the surface and leaves
// it (their segment's length the arc's, not the chord's), or none where it does not touch it.
struct PathState {
  std::array<Point, kMaxPathPoints> position;  // q_j [m]
  std::array<Point, kMaxPathPoints> velocity;  // qdot_j [m/s]
  std::array<int, kMaxPathPoints> state;       // a free node's state index, else -1
  std::array<int, kMaxPathPoints> node;        // the node at q_j, else -1 (fixed, wrap)
  // a point on a wrap surface: the body it moves with (-1: the ground), and where it is in
  // the body's frame; -2 for the other points
  std::array<int, kMaxPathPoints> wrap_body;
  std::array<Coordinates, kMaxPathPoints> wrap_point;
  PathGeometry geometry;
  double length_rate = 0.0;  // ldot [m/s]
};

// The build's steps: element e's path resolved; the free nodes' loads, each along its
// direction.
void AddPath(NetworkModel& m, std::size_t e);
void ResolveSpace(NetworkModel& m);
// The pattern's: the paths' entries, and their slots.
void AddSpacePattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs);
void FindSpaceSlots(NetworkModel& m, const std::function<int(int, int)>& slot);
// The state index of each point of the link's path (-1 unless a free node), in order.
void PathStates(const NetworkModel& m, const Link& link, std::vector<int>& states);

// NetworkSystem's methods of the same names (network.h).
int SegmentCount(const NetworkModel& m, int e);
double SegmentLength(const NetworkModel& m, int e, int k, double t, const double* y);
double NodeCoordinate(const NetworkModel& m, int i, int c, double t, const double* y);
double NodeCoordinateRate(const NetworkModel& m, int i, int c, double t, const double* y);

void MeasureLink(const NetworkModel& m, int e, double t, const double* y, PathState& state);
double SpaceLengtheningRate(const NetworkModel& m, int e, double t, const double* y);
// The sum of free node f's loads, each along its direction [N].
Coordinates DirectedLoad(const NetworkModel& m, const FreeNode& f, double t, const double* y);
// Every segment longer than kMinSegmentLength at the start (ParameterError).
void CheckInitialPaths(const NetworkModel& m, double t, const double* y);
void SpaceRightHandSide(const NetworkModel& m, double t, const double* y, double* ydot);
void SpaceJacobian(const NetworkModel& m, double t, const double* y, double* values);
void ObserveSpace(const NetworkModel& m, double t, const double* y, NetworkSample& sample);
}  // namespace musclesim::network
