// NetworkSystem (network.h): the model built, and each method the algorithm of the same name
// over it (src/dynamics/network_*.h).
#include "musclesim/dynamics/network.h"

#include <string>
#include <utility>

#include "dynamics/network_build.h"
#include "dynamics/network_control.h"
#include "dynamics/network_diagnosis.h"
#include "dynamics/network_evaluation.h"
#include "dynamics/network_sensitivity.h"
#include "dynamics/network_skeleton.h"
#include "dynamics/network_space.h"

namespace musclesim {

NetworkSystem::NetworkSystem(std::vector<Node> nodes, std::vector<Element> elements,
                             std::vector<NodeLoad> loads, std::vector<Controller> controllers,
                             Space space, std::shared_ptr<const Skeleton> skeleton) {
  model_.nodes = std::move(nodes);
  model_.elements = std::move(elements);
  model_.loads = std::move(loads);
  model_.controllers = std::move(controllers);
  model_.space = space;
  model_.skeleton = std::move(skeleton);
  network::Build(model_);
}

void NetworkSystem::InitialState(double t_start, double* y) const {
  network::InitialState(model_, t_start, y);
}

void NetworkSystem::CheckInitialState(double t, const double* y) const {
  network::CheckInitialState(model_, t, y);
}

void NetworkSystem::RightHandSide(double t, const double* y, double* ydot,
                                  NetworkScratch& scratch) const {
  network::RightHandSide(model_, t, y, ydot, scratch);
}

void NetworkSystem::Jacobian(double t, const double* y, double* values,
                             NetworkScratch& scratch) const {
  network::Jacobian(model_, t, y, values, scratch);
}

double NetworkSystem::Length(int e, double t, const double* y) const {
  return network::Length(model_, e, t, y);
}

double NetworkSystem::LengtheningRate(int e, double t, const double* y) const {
  return network::LengtheningRate(model_, e, t, y);
}

bool NetworkSystem::Spans(int e, int k) const { return network::Spans(model_, e, k); }

int NetworkSystem::SegmentCount(int e) const { return network::SegmentCount(model_, e); }

double NetworkSystem::SegmentLength(int e, int k, double t, const double* y) const {
  return network::SegmentLength(model_, e, k, t, y);
}

double NetworkSystem::KinkValue(const Kink& kink, double t, const double* y) const {
  return network::KinkValue(model_, kink, t, y);
}

std::vector<double> NetworkSystem::Breakpoints(double t0, double t1) const {
  return network::Breakpoints(model_, t0, t1);
}

void NetworkSystem::Observe(double t, const double* y, NetworkSample& sample) const {
  network::Observe(model_, t, y, sample);
}

void NetworkSystem::ObserveElement(int e, double t, const double* y, ElementSample& out) const {
  network::ObserveElement(model_, e, t, y, out);
}

double NetworkSystem::NodePosition(int i, double t, const double* y) const {
  return dimensions() == 1 ? network::PositionOf(model_, model_.ends[i], t, y)
                           : network::NodeCoordinate(model_, i, 0, t, y);
}

double NetworkSystem::NodeVelocity(int i, double t, const double* y) const {
  return dimensions() == 1 ? network::VelocityOf(model_, model_.ends[i], t, y)
                           : network::NodeCoordinateRate(model_, i, 0, t, y);
}

double NetworkSystem::NodeCoordinate(int i, int c, double t, const double* y) const {
  return network::NodeCoordinate(model_, i, c, t, y);
}

double NetworkSystem::NodeCoordinateRate(int i, int c, double t, const double* y) const {
  return network::NodeCoordinateRate(model_, i, c, t, y);
}

double NetworkSystem::LoadOn(int i, double t, const double* y) const {
  return network::LoadOn(model_, i, t, y);
}

std::string NetworkSystem::NonFiniteCause(double t, const double* y) const {
  return network::NonFiniteCause(model_, t, y);
}

int NetworkSystem::FindNode(std::string_view name) const { return network::FindNode(model_, name); }

int NetworkSystem::FindElement(std::string_view name) const {
  return network::FindElement(model_, name);
}

int NetworkSystem::FindController(std::string_view name) const {
  return network::FindController(model_, name);
}

NetworkSystem::ElementPartials NetworkSystem::Along(int e, double t, const double* y,
                                                    const double* s) const {
  return network::Along(model_, e, t, y, s);
}

double NetworkSystem::NodeVelocityAlong(int node, double t, const double* y,
                                        const double* s) const {
  return network::NodeVelocityAlong(model_, node, t, y, s);
}

void NetworkSystem::AddTension(int e, double t, const double* y, double tension,
                               double* ydot) const {
  network::AddTension(model_, e, t, y, tension, ydot);
}

void NetworkSystem::HoldActivation(int e, double value) {
  network::HoldActivation(model_, e, value);
}

}  // namespace musclesim
