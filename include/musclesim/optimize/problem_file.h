// The problem file of `musclesim optimize` (docs/guide/optimize.md): a base scenario, the
// controls, the final values, IPOPT's settings and where the results go.
//
//   base: antagonist_pair.yaml           # relative to this file
//   intervals: 50
//   controls:
//     - {actuator: flexor, bounds: [0.0, 1.0], effort: {weight: 1.0, power: 2}}
//   final_values:
//     - {column: load.position, value: 0.072}
//     - {column: load.velocity, bounds: [-1.0e-3, 1.0e-3]}
//   optimizer: {tolerance: 1.0e-8, max_iterations: 500}
//   output: {scenario: optimum.yaml, summary: optimum.json, trajectory: optimum.csv}
#pragma once

#include <string>

#include "musclesim/io/readers/document.h"
#include "musclesim/optimize/optimal_control.h"

namespace musclesim {

struct OptimizeOutputs {
  std::string scenario;    // the base with the optimal controls as tables: `musclesim run` it
  std::string summary;     // JSON: status, objective, violation, iterations, re-simulation
  std::string trajectory;  // CSV: the re-simulated run of the optimum
};

struct ProblemFile {
  std::string path;  // the problem file
  std::string base;  // the base scenario's path (relative to the working directory)
  OptimalControlProblem problem;
  OptimizeOptions options;
  OptimizeOutputs outputs;
};

// Reads and checks a problem file. Every error is an InputError naming the file, line and
// column, the key path, the value and the rule; the base scenario's errors are its own.
ProblemFile LoadProblemFile(const std::string& path);

// A problem given as a document (a Python call's arguments, io/readers/document.h) on `scenario`:
// the keys of a problem file but `base` and `output`, read and checked by the same rules, its
// errors named after `name`. Nothing is written, so `outputs` stay empty.
ProblemFile ReadProblem(const Document& document, const std::string& name,
                        const Scenario& scenario);

}  // namespace musclesim
