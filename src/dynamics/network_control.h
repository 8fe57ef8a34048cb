// Private: feedback control of a network (docs/model.md section 11): the controllers' loops
// built, their commands, integral states and Jacobian terms (network_control.cc; in the plane
// and in space, space_control.cc).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "musclesim/dynamics/network_model.h"
#include "musclesim/dynamics/network_sample.h"

namespace musclesim::network {

// What a controller computes at (t, y), with derivatives along its columns (on a line; in 2
// or 3 dimensions they are SpaceControlJacobian's, and these stay 0).
struct Command {
  double reference, measured, error;
  double value;                   // c
  double by_state[kLoopColumns];  // dc/dy at the columns
  double error_by_state[kLoopColumns];
  double high, low;  // c beyond which no actuator can respond further
};

// The build's step for controllers, and its steps: controllers[k]'s loop with what it
// measures; the measured node's coordinate (named in 2 or 3 dimensions, within the
// dimensions); the actuator `name` at controllers[k].`key`, checked to be one it may drive;
// the actuators it drives, their drivers noted in `driver`; the refusal of a tension measured
// through a controller's output; the loop's state columns; their pattern entries and slots.
void ResolveControllers(NetworkModel& m, int& states);
Loop MeasuredLoop(const NetworkModel& m, std::size_t k);
void RequireCoordinate(const NetworkModel& m, std::size_t k);
int DrivableActuator(const NetworkModel& m, std::size_t k, const char* key, const std::string& name,
                     const std::vector<int>& driver);
void AttachDriven(NetworkModel& m, std::size_t k, Loop& loop, std::vector<int>& driver);
void RequireNoAlgebraicLoop(const NetworkModel& m, std::size_t k, const std::vector<int>& driver);
void PlaceLoopColumns(NetworkModel& m, std::size_t k);
void AddControlPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs);
void FindControlSlots(NetworkModel& m, const std::vector<std::pair<int, int>>& pairs);

// What controller k commands at (t, y).
Command CommandOf(const NetworkModel& m, int k, double t, const double* y);
// A controlled actuator's command before its clamp: level +- c, or c.
double UnclampedOutput(const NetworkModel& m, int e, const Command& command, double t);
// A controlled actuator's activation (no activation dynamics) or excitation, clamped.
double ControlOutput(const NetworkModel& m, int e, double t, const double* y);
// udot's excitation e of an actuator with activation dynamics: its signal's, or its
// controller's output.
double ExcitationOf(const NetworkModel& m, int e, double t, const double* y);
// zdot = weight err: the weight of the integral's fade near the bounds, and its derivative
// by c.
struct IntegralFade {
  double weight, by_value;
};
IntegralFade FadeOf(const Command& command, double ki);
// zdot with its fade near the bounds, and its derivatives along the loop's columns.
double IntegralRate(const Command& command, double ki, double* by_state);
void ControlRightHandSide(const NetworkModel& m, double t, const double* y, double* ydot);
// Adds the feedback terms dT/du du/dy, d(udot)/de de/dy and d(zdot)/dy (before the rows'
// 1/m scaling).
void ControlJacobian(const NetworkModel& m, double t, const double* y, double* values);
void ObserveControllers(const NetworkModel& m, double t, const double* y, NetworkSample& sample);
// The one change a model takes after it is built: an actuator's activation (or excitation)
// held at `value` from now on, by the stepper that owns its copy (NetworkSystem::HoldActivation).
void HoldActivation(NetworkModel& m, int e, double value);

// In 2 or 3 dimensions (space_control.cc): a loop's columns (the free points of the measured
// element's path, or the measured node's coordinate and its rate, then an activation state
// and the integral); the rows a driven actuator's output reaches (its activation row, or the
// acceleration rows of its path's free points); their pattern and entries; the measured
// quantity and its rate, with (unless nullptr) their derivatives along the loop's columns;
// the feedback terms of the Jacobian (before the rows' 1/m).
void PlaceSpaceLoopColumns(NetworkModel& m, std::size_t k);
void DrivenRows(const NetworkModel& m, int e, std::vector<int>& rows);
void AddSpaceControlPattern(const NetworkModel& m, std::vector<std::pair<int, int>>& pairs);
void FindSpaceControlSlots(NetworkModel& m, const std::vector<std::pair<int, int>>& pairs);
double MeasureInSpace(const NetworkModel& m, int k, double t, const double* y, double& rate,
                      double* measured_by = nullptr, double* rate_by = nullptr);
void SpaceControlJacobian(const NetworkModel& m, double t, const double* y, double* values);

}  // namespace musclesim::network
