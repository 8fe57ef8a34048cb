// Thelen 2003's four muscle curves as OpenSim 4.6's Thelen2003Muscle defines them (docs/model.md
// 14.5), normalised as its properties are: f(l~) of the fiber length over the optimal one,
// f_v of the lengthening velocity over v_max l_opt, the tendon's force of its strain. Like
// Millard's, musclesim runs no muscle of this family: `musclesim import` converts it to
// family degroote2016 (model/degroote_conversion.h).
#pragma once

namespace musclesim {

// OpenSim's properties, its names, its defaults.
struct ThelenCurves {
  double FmaxTendonStrain = 0.04;            // the tendon's strain at the isometric force
  double FmaxMuscleStrain = 0.6;             // the fiber's passive strain at the isometric force
  double KshapeActive = 0.45;                // the active Gaussian's shape
  double KshapePassive = 5.0;                // the passive exponential's
  double Af = 0.25;                          // the force-velocity curve's shape (Hill's a / F0)
  double Flen = 1.4;                         // its lengthening plateau, over F0
  double fv_linear_extrap_threshold = 0.95;  // where, over Flen, it goes on as a line
};

// Throws ParameterError naming the property by OpenSim's name.
void Validate(const ThelenCurves& curves);

namespace thelen2003 {

// exp(-(l~ - 1)^2 / KshapeActive)
double ActiveForceLength(const ThelenCurves& c, double normalized_length);
// (exp(KshapePassive (l~ - 1) / FmaxMuscleStrain) - 1) / (exp(KshapePassive) - 1) above
// l~ = 1, 0 below
double PassiveForceLength(const ThelenCurves& c, double normalized_length);
// f_v at activation 1 (Thelen's maximum velocity scales as 0.25 + 0.75 a): Thelen 2003's
// eqs. 6-7 solved for the force, the lengthening branch continued as a line beyond
// fv_linear_extrap_threshold Flen; 0 shortening faster than v_max (OpenSim's clamp)
double ForceVelocity(const ThelenCurves& c, double normalized_lengthening);
// an exponential toe to 0.33 at a third of the curve's strain, Thelen's etoe (exactly
// 99 e0 e^3 / (166 e^3 - 67)), linear beyond to 1 at FmaxTendonStrain; 0 when slack
double TendonForceLength(const ThelenCurves& c, double strain);

}  // namespace thelen2003

}  // namespace musclesim
