#include "studies/sweep_base.h"

namespace musclesim {

std::unique_ptr<SweepBase> OpenSweepBase(const SweepSpec& spec) {
  return spec.network ? OpenNetworkSweepBase(spec.base) : OpenActuatorSweepBase(spec.base);
}

}  // namespace musclesim
