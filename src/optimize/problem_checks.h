// Private: an optimal control problem checked against its scenario, and what multiple
// shooting needs of it resolved to indices: each control's actuator, each column's place
// among the run's differentiated columns (scenario/sensitivity_columns.h), each free
// parameter's handle.
#pragma once

#include <vector>

#include "musclesim/optimize/optimal_control.h"
#include "musclesim/scenario/parameter.h"

namespace musclesim {

struct ProblemIndex {
  std::vector<int> elements;  // per control, its actuator element
  // per control, its activation's state with activation dynamics (the control is then the
  // excitation), else -1; and whether its first value sets the activation's start
  std::vector<int> activation_states;
  std::vector<char> moves_start;
  std::vector<Parameter> parameters;  // per free parameter, its handle
  // the columns the terms read, once each: their indices among the differentiated columns,
  // and for each the state it reads with its sign (-1: a function of the state)
  std::vector<int> columns;
  std::vector<int> column_states;
  std::vector<double> column_signs;
  // per final value, path bound, tracking and terminal term: its entry in `columns`
  std::vector<int> finals, paths, tracked, terminals;
};

// Checks `problem` (InputError naming the entry, its value and the rule) and resolves it.
ProblemIndex CheckProblem(const OptimalControlProblem& problem);

}  // namespace musclesim
