// Model parameters as Python values: the `model:` block's keys, so that Model(dict) takes
// them back.
#pragma once

#include <pybind11/pybind11.h>

#include "musclesim/model/active_length.h"
#include "musclesim/model/tension.h"

namespace musclesim::python {

// {amplitude [-], width [1/m^2], center [m]}.
pybind11::dict GaussianDict(const Gaussian& g);

// The `model:` block's keys and values, from its family's description: every field (an
// optional one where given), explicit gaussians (a fit's result in its place).
pybind11::dict ParamsDict(const ModelParams& p);

}  // namespace musclesim::python
