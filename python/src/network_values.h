// The numeric columns of a network's CSV (io/network_csv.h) and their values in one sample,
// in the same order; the `phase` columns (text) are left out.
#pragma once

#include <string>
#include <vector>

#include "musclesim/dynamics/network.h"

namespace musclesim::python {

// The network CSV's column names without "t" and without the `phase` columns.
std::vector<std::string> NumericNetworkColumns(const NetworkSystem& system);

// Appends the values of NumericNetworkColumns(system) in `sample` to `values`.
void AppendNumericNetworkValues(const NetworkSystem& system, const NetworkSample& sample,
                                std::vector<double>& values);


}  // namespace musclesim::python
