#include "studies/sweep_base.h"

#include "musclesim/errors.h"
#include "musclesim/io/sensitivity_run.h"

namespace musclesim {

std::unique_ptr<SweepBase> OpenSweepBase(const SweepSpec& spec) {
  // a sweep's points are plain runs reduced to metrics: a list that would be ignored is refused
  if (HasSensitivities(spec.base)) {
    throw InputError(spec.base + ": sensitivities: a sweep runs its points without "
                     "sensitivities; remove the key from the base scenario (musclesim run "
                     "computes them)");
  }
  return spec.network ? OpenNetworkSweepBase(spec.base) : OpenActuatorSweepBase(spec.base);
}

}  // namespace musclesim
