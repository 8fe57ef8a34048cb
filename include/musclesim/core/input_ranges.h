// The range of every number the readers and the command line accept, each with the reason
// for its bounds (docs/tests.md). Finite is not enough: 1e308 is finite, and 1e308 + 1e308 is
// not. The bounds keep each sum and product of the dynamics (m_eff xddot = F_load - T - c xdot - k
// (x - l0)) and of the time grid far inside double precision, and they lie beyond anything a
// muscle-like actuator or its test rig does, so no sensible scenario meets them.
#pragma once

#include <string>

namespace musclesim {

// The numbers a value may take, with its unit and the reason for the bounds: messages print
// all three, so that a user learns why, not only that.
struct InputRange {
  double min = 0.0;            // lowest value accepted [unit]
  double max = 0.0;            // highest value accepted [unit]
  const char* unit = "";       // printed after the bounds ("s", "m", "N") [-]
  const char* why = "";        // why the bounds are where they are, for messages [-]
  bool min_exclusive = false;  // refuse `min` itself (> min rather than >= min) [-]
  bool max_exclusive = false;  // refuse `max` itself (< max rather than <= max) [-]

  // False for NaN.
  bool Contains(double value) const {
    return (min_exclusive ? value > min : value >= min) &&
           (max_exclusive ? value < max : value <= max);
  }
  // "must be from -1e+09 to 1e+09 [s]: <why>" or "must be > 0 and <= 1000 [m]: <why>"
  std::string Rule() const;
  // The bounds alone: "from -1e+09 to 1e+09", "> 0 and <= 1000", ">= 1e-14 and < 1".
  std::string Bounds() const;
};

// Times [s]: start and end of the run, waveform times.
inline constexpr InputRange kTimeRange{
    -1e9, 1e9, "s",
    "beyond 1e9 s (32 years) a microsecond is no longer resolved (doubles there are 1.2e-7 s "
    "apart), and within it every span is finite"};

// The shortest span and output interval, relative to the time scale max(1 s, |start|, |end|)
// [-]: 1e-12 is about 4500 roundoffs, far above the 2 roundoffs CVODE needs between two
// output times; spans are 1000 times that, room for the default 1000 rows.
inline constexpr double kMinIntervalRelative = 1e-12;
inline constexpr double kMinSpanRelative = 1e-9;

// The time scale of a run [s]: max(1 s, |start|, |end|). The shortest span, interval and
// step are fractions of it, so that they stay many roundoffs wide.
double TimeScale(double t_start, double t_end);

// Lengths [m]: the initial length (> 0), rest lengths and anchors, limits, fit points.
inline constexpr InputRange kLengthRange{
    0.0, 1e3, "m",
    "a kilometre is beyond any actuator, and keeps stiffness times length within range", true};
inline constexpr InputRange kPositionRange{
    -1e3, 1e3, "m",
    "a kilometre is beyond any actuator, and keeps stiffness times length within range"};

// A tendon's slack length [m]: from 0 (taut from the start), and De Groote's tendon's, > 0
// (its law is normalised by it).
inline constexpr InputRange kSlackLengthRange{
    0.0, 1e3, "m", "a slack length is a length, and a kilometre is beyond any actuator"};
inline constexpr InputRange kDeGrooteSlackRange{
    0.0, 1e3, "m", "De Groote's tendon is normalised by its slack length", true};

// An exponential tendon's rate alpha [1/m]: its tension grows e-fold over 1/alpha.
inline constexpr InputRange kTendonRateRange{
    0.0, 1e9, "1/m", "a tension growing e-fold over less than a nanometre is no tendon's", true};

// Speeds [m/s]: the initial lengthening rate, the phase tolerance.
inline constexpr InputRange kSpeedRange{-1e3, 1e3, "m/s",
                                        "three times the speed of sound, beyond any actuator"};
inline constexpr InputRange kPhaseToleranceRange{
    0.0, 1e3, "m/s", "three times the speed of sound, beyond any actuator"};

// Forces [N]: force-load waveform values, a force held fixed in identification.
inline constexpr InputRange kForceRange{
    -1e9, 1e9, "N",
    "1e9 N (100,000 tonnes-force) is beyond any actuator or rig, and sums of loads stay finite"};
inline constexpr InputRange kPositiveForceRange{
    0.0, 1e9, "N",
    "1e9 N (100,000 tonnes-force) is beyond any actuator or rig, and sums of loads stay finite",
    true};

// Masses [kg]: the actuator's and a hanging load's.
inline constexpr InputRange kMassRange{
    1e-9, 1e9, "kg",
    "a microgram to a million tonnes: accelerations F/m stay finite (1e9 N / 1e-9 kg = "
    "1e18 m/s^2)"};

// A tendon's strain at its maximum isometric force [-] (De Groote's tendon, OpenSim's 0.049
// by default).
inline constexpr InputRange kTendonStrainRange{
    0.0, 1.0, "-",
    "a tendon stretched by more than its own length at the muscle's full force is no tendon", true};

// Stiffness [N/m] and damping [N s/m]: of the actuator and of spring loads.
inline constexpr InputRange kStiffnessRange{
    0.0, 1e12, "N/m",
    "stiffer than any rig (a steel bar 1 cm^2 by 1 mm is 2e10 N/m), and k (x - l0) stays "
    "below 1e15 N"};
inline constexpr InputRange kDampingRange{0.0, 1e12, "N s/m",
                                          "beyond any damper, and c xdot stays below 1e15 N"};

// Gravity [m/s^2] of a hanging mass.
inline constexpr InputRange kGravityRange{-1e3, 1e3, "m/s^2",
                                          "about 100 g, beyond any rig; m g stays finite"};

// The components of a direction [-] (a network load's in 2 or 3 dimensions): it is made a
// unit vector, so only their ratios matter.
inline constexpr InputRange kDirectionRange{
    -1e3, 1e3, "-", "a direction is made a unit vector: only its components' ratios matter"};

// The time constants accepted [s]: muscles take 5 to 60 ms; below 0.1 ms the lag is in effect
// instantaneous (give the activation itself) and only makes the system stiff, and 10 s is
// slower than any muscle-like actuator.
inline constexpr double kMinActivationTimeConstant = 1e-4;
inline constexpr double kMaxActivationTimeConstant = 10.0;

// Activation dynamics (docs/model.md section 8): the time constants [s] and an initial
// activation [-].
inline constexpr InputRange kActivationTimeConstantRange{
    kMinActivationTimeConstant, kMaxActivationTimeConstant, "s",
    "muscles take 5 to 60 ms; below 0.1 ms the lag is in effect instantaneous (give activation "
    "instead) and only makes the run stiff, and 10 s is slower than any muscle-like actuator"};
inline constexpr InputRange kActivationRange{0.0, 1.0, "-",
                                             "an activation is a fraction of the full activation"};
// The smoothings of the switch between the time constants (docs/model.md 8.1): De Groote's
// tanh steepness b [-] (OpenSim's activation_dynamics_smoothing; below 1e-3 the rate is the
// two constants' mean, above 1e4 the switch is a step the integrator cannot follow smoothly)
// and MuJoCo's tausmooth [-], the width in e - u of its quintic switch (0: the step; from 2
// on it spans every e - u and both ends are blends, as MuJoCo computes them; up to 1e9, where
// the blend is the two constants' mean to rounding).
inline constexpr InputRange kActivationSmoothingRange{
    1e-3, 1e4, "-",
    "b of tanh(b (e - u)): below 1e-3 the two time constants merge into their mean, above 1e4 "
    "the switch is a step (leave the smoothing to family thelen2003 then)"};
inline constexpr InputRange kTauSmoothRange{
    0.0, 1e9, "-",
    "the width in e - u of MuJoCo's switch: 0 is the step, from 2 on it spans every e - u"};

// A controller's gains [per unit measured, times s for ki^-1 and kd]: beyond 1e9 an error of
// a nanometre or a nanonewton already saturates the output (the loop is a switch), and the
// products of gains and errors stay finite.
inline constexpr InputRange kGainRange{
    -1e9, 1e9, "per unit measured",
    "a gain of 1e9 saturates the output on an error of 1e-9 of its unit: beyond it the loop is "
    "a switch"};
// A controller's feedforward [-]: its output is clamped to [0, 1] (a pair's command acts
// within [-1, 1]), so a larger offset only holds the output at a bound.
inline constexpr InputRange kFeedforwardRange{
    -1.0, 1.0, "-",
    "the output is clamped to [0, 1] and a pair's command acts within [-1, 1]: a larger offset "
    "only holds it at a bound"};

// Frequency of a sine [Hz].
inline constexpr InputRange kFrequencyRange{
    0.0, 1e6, "Hz",
    "a period below a microsecond is not resolved at times up to 1e9 s (doubles there are "
    "1.2e-7 s apart)"};

// The values of a fit's target points [-]: shapes of height about 1.
// The Gaussians f_L is fitted with (a fit block's count, an identification's): one at least,
// and past a dozen the least-squares system of their amplitudes is ill-conditioned.
inline constexpr InputRange kGaussianCountRange{
    1, 12, "-",
    "past a dozen Gaussians the fit of their amplitudes is ill-conditioned on a measured curve"};
inline constexpr InputRange kFitValueRange{
    -1e6, 1e6, "-",
    "a target is a shape of height about 1; its squares in the cost stay far from overflow"};

// The most breakpoints (pulse edges, table points) a waveform may have [-]: each is a stop
// time where the integrator restarts, and each takes memory.
inline constexpr double kMaxBreakpoints = 5e6;

}  // namespace musclesim
