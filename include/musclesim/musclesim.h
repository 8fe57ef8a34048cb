// musclesim in one include: the tension model, the actuator and network dynamics, the
// CVODE simulation and the scenario files. Studies (sweeps, identification, plots) have their
// own headers under musclesim/studies/. A program that needs only the curves includes
// musclesim/model/tension.h and links musclesim::model alone.
#pragma once

#include "musclesim/errors.h"
#include "musclesim/model/gaussian_fit.h"
#include "musclesim/model/tension.h"
#include "musclesim/dynamics/actuator.h"
#include "musclesim/dynamics/controller.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/network.h"
#include "musclesim/dynamics/waveform.h"
#include "musclesim/solver/simulation.h"
#include "musclesim/solver/stepper.h"
#include "musclesim/io/network_csv.h"
#include "musclesim/io/network_scenario.h"
#include "musclesim/io/run_scenario.h"
#include "musclesim/io/scenario.h"
#include "musclesim/io/trajectory_csv.h"
