// musclesim in one include: the tension model, the network dynamics, the CVODE simulation, the
// in-memory scenario with its parameter handles, runs and sensitivities, and the scenario
// files. Sweeps, identification and plots have their own headers (musclesim/sweep/,
// musclesim/identify/, musclesim/plot/). A program that needs only the curves includes
// musclesim/model/tension.h and links musclesim::model alone.
#pragma once

#include "musclesim/core/errors.h"
#include "musclesim/model/gaussian_fit.h"
#include "musclesim/model/tension.h"
#include "musclesim/dynamics/actuator.h"
#include "musclesim/dynamics/controller.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/network.h"
#include "musclesim/dynamics/waveform.h"
#include "musclesim/solver/simulation.h"
#include "musclesim/solver/stepper.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "musclesim/io/writers/run_csv.h"
#include "musclesim/io/readers/scenario_yaml.h"
