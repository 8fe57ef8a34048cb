#include "musclesim/dynamics/controller.h"

#include <cmath>
#include <utility>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/controller_gains.h"
#include "musclesim/core/enum_names.h"

namespace musclesim {

constexpr EnumName<MeasuredQuantity> kMeasuredQuantityNames[] = {
    {MeasuredQuantity::kLength, "length"},
    {MeasuredQuantity::kTension, "tension"},
    {MeasuredQuantity::kPosition, "position"},
};

std::string_view ToString(MeasuredQuantity quantity) {
  return ToString(kMeasuredQuantityNames, quantity);
}

MeasuredQuantity ParseMeasuredQuantity(std::string_view text) {
  return Parse(kMeasuredQuantityNames, "quantity", text);
}

std::string_view CoordinateName(int coordinate) {
  constexpr std::string_view kNames[] = {"x", "y", "z"};
  return coordinate >= 0 && coordinate < 3 ? kNames[coordinate] : "none";
}

int ParseCoordinate(std::string_view text) {
  for (int c = 0; c < 3; ++c) {
    if (text == CoordinateName(c)) return c;
  }
  throw ParameterError("coordinate", std::string(text), "must be one of x, y, z");
}

namespace {

void ValidateMeasurement(const Measurement& m) {
  if (m.element.empty() == m.node.empty()) {
    throw ParameterError("measure", m.element.empty() ? "neither" : "both",
                         "must name exactly one of `element` and `node`");
  }
  if (!m.node.empty() && m.quantity != MeasuredQuantity::kPosition) {
    throw ParameterError("measure.quantity", std::string(ToString(m.quantity)),
                         "a node's measured quantity is its position");
  }
  if (!m.element.empty() && m.quantity == MeasuredQuantity::kPosition) {
    throw ParameterError("measure.quantity", "position",
                         "an element's measured quantity is its length or its tension");
  }
  if (m.coordinate == Measurement::kNoCoordinate) return;
  if (m.coordinate < 0 || m.coordinate > 2) {
    throw ParameterError("measure.coordinate", std::to_string(m.coordinate),
                         "must be x, y or z (0, 1 or 2)");
  }
  if (!m.element.empty()) {
    throw ParameterError("measure.coordinate", std::string(CoordinateName(m.coordinate)),
                         "only a node's position has coordinates: an element's length and "
                         "tension are numbers");
  }
}

}  // namespace

void Validate(const Controller& c) {
  ValidateMeasurement(c.measure);
  ValidateSignals(ControllerSignals(), c);
  try {
    ValidateFields(ControllerGains().front(), c.gains);
  } catch (const ParameterError& error) {
    throw ParameterError("gains." + error.path(), error.value(), error.rule());
  }
  if (c.measure.quantity == MeasuredQuantity::kTension) {
    // d(err)/dt would need dT/dt, which depends on the accelerations being computed
    Require(c.gains.kd == 0.0, "gains.kd", c.gains.kd,
            "must be 0 on a tension: its rate would be an algebraic loop (docs/model.md 11)");
  }
  if (c.drives.empty() == !c.co_contraction) {
    throw ParameterError("drives", c.drives.empty() ? "none" : c.drives,
                         "a controller needs exactly one of `drives` and `co_contraction`");
  }
  if (c.co_contraction) {
    const CoContraction& pair = *c.co_contraction;
    if (pair.first.empty() || pair.second.empty() || pair.first == pair.second) {
      throw ParameterError("co_contraction.actuators", pair.first + ", " + pair.second,
                           "must name two different actuators");
    }
  }
}

namespace {

Controller Law(std::string name, Measurement measure, Waveform reference, PidGains gains) {
  Controller c;
  c.name = std::move(name);
  c.measure = std::move(measure);
  c.reference = std::move(reference);
  c.gains = gains;
  return c;
}

}  // namespace

Controller Controller::Pid(std::string name, Measurement measure, Waveform reference,
                           PidGains gains, std::string drives) {
  Controller c = Law(std::move(name), std::move(measure), std::move(reference), gains);
  c.drives = std::move(drives);
  return Validated(std::move(c));
}

Controller Controller::CoContracting(std::string name, Measurement measure, Waveform reference,
                                     PidGains gains, CoContraction pair) {
  Controller c = Law(std::move(name), std::move(measure), std::move(reference), gains);
  c.co_contraction = std::move(pair);
  return Validated(std::move(c));
}

}  // namespace musclesim
