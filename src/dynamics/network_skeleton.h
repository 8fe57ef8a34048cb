// Private: a network with a skeleton (docs/model.md 15): the skeleton's kinematics at a state,
// its part of the right-hand side, the pattern and Jacobian of such a network, and what
// Observe records of it (network_skeleton.cc).
#pragma once

#include <utility>
#include <vector>

#include "musclesim/dynamics/network_model.h"
#include "musclesim/dynamics/network_sample.h"
#include "musclesim/dynamics/network_scratch.h"
#include "dynamics/network_space.h"

namespace musclesim::network {

// The skeleton's kinematics at the q and u of y, computed once for each distinct (q, u) on
// each thread: every node on a body reads it, and the right-hand side's forces and ABA use
// it. (The cache is per thread, so threads integrating the same network share nothing.)
SkeletonWorkspace& SkeletonAt(const NetworkModel& m, const double* y);
// Node i on a body: coordinate c of its position and of its velocity.
double BodyPointCoordinate(const NetworkModel& m, int i, int c, const double* y);
double BodyPointRate(const NetworkModel& m, int i, int c, const double* y);
// Adds to the workspace's forces the force -T G_j of a path's point j on a body (a node on
// a body, or a point where the path touches a wrap surface); nothing for another point.
void AddPathForce(const NetworkModel& m, const PathState& path, std::size_t j, double tension,
                  SkeletonWorkspace& ws);
// The skeleton's rows of ydot: q' = u, and u' by ABA from the joints' damping and the forces
// added to the workspace (SpaceRightHandSide adds the paths' before).
void SkeletonRates(const NetworkModel& m, const double* y, SkeletonWorkspace& ws, double* ydot);
// Throws ParameterError ("joints[0].axis") unless, in the plane, every joint keeps its child in
// the x-y plane: frames turned about z only, revolute axes along z, prismatic ones across it.
void CheckPlanarSkeleton(const NetworkModel& m);
// Each wrap surface's unit axis and side axis x in its body's frame (m.wraps).
void PlaceWraps(NetworkModel& m);
// A network with a skeleton has a dense pattern: every pair of states.
void AddSkeletonPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs);
// Its Jacobian, column by column, by central differences of the right-hand side (until the
// exact blocks of docs/model.md 15.5 are in: ABA's derivatives and the paths' terms).
void SkeletonJacobian(const NetworkModel& m, double t, const double* y, double* values,
                      NetworkScratch& scratch);
// The coordinates, speeds and moment arms of the sample.
void ObserveSkeleton(const NetworkModel& m, double t, const double* y, NetworkSample& sample);
// Whether element e's length changes with coordinate k: some of its path's points move with k
// and some do not.
bool Spans(const NetworkModel& m, int e, int k);
}  // namespace musclesim::network
