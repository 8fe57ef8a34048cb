#include "musclesim/dynamics/loads.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/load_kinds.h"

namespace musclesim {

void Validate(const Load& load) {
  switch (load.kind) {
    case LoadKind::kForce: Validate(load.force); break;
    case LoadKind::kSpring:
    case LoadKind::kMass: ValidateFields(*VariantOf(LoadVariants(), load), load); break;
  }
}

Load Load::Force(Waveform force) {
  Load load;
  load.kind = LoadKind::kForce;
  load.force = std::move(force);
  return Validated(std::move(load));
}

Load Load::Constant(double force) { return Force(Waveform::Constant(force)); }

Load Load::Spring(double stiffness, double anchor) {
  Load load;
  load.kind = LoadKind::kSpring;
  load.stiffness = stiffness;
  load.anchor = anchor;
  return Validated(std::move(load));
}

Load Load::Mass(double mass, double gravity) {
  Load load;
  load.kind = LoadKind::kMass;
  load.mass = mass;
  load.gravity = gravity;
  return Validated(std::move(load));
}

LoadSet::LoadSet(std::vector<Load> loads) : loads_(std::move(loads)) {
  for (std::size_t i = 0; i < loads_.size(); ++i) {
    try {
      Validate(loads_[i]);
    } catch (const ParameterError& e) {
      throw ParameterError("load[" + std::to_string(i) + "]." + e.path(), e.value(), e.rule());
    }
  }
  for (const Load& load : loads_) {
    switch (load.kind) {
      case LoadKind::kForce: forces_.push_back(load.force); break;
      case LoadKind::kSpring:
        spring_stiffness_ += load.stiffness;
        spring_pull_ += load.stiffness * load.anchor;
        break;
      case LoadKind::kMass:
        weight_ += load.mass * load.gravity;
        added_mass_ += load.mass;
        break;
    }
  }
}

double LoadSet::Force(double t, double x) const {
  double force = weight_ + spring_pull_ - spring_stiffness_ * x;
  for (const Waveform& w : forces_) force += w.Evaluate(t);
  return force;
}

std::vector<double> LoadSet::Breakpoints(double t0, double t1) const {
  std::vector<double> times;
  for (const Waveform& w : forces_) {
    const std::vector<double> own = w.Breakpoints(t0, t1);
    times.insert(times.end(), own.begin(), own.end());
  }
  SortUnique(times);
  return times;
}

}  // namespace musclesim
