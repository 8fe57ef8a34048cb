#include "io/import/conversion_report.h"

#include <cstdio>
#include <string>

#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

// Three significant digits: a departure is a measure, not a value to read back.
std::string Short(double x) { return FormatSignificant(x, 3); }

// An interval's end: six significant digits (a property's value, or one derived from it).
std::string Bound(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string Departure(const CurveDeparture& d, const std::string& argument) {
  return "largest departure " + Short(d.largest) + " f_iso at " + argument + " = " + Short(d.at) +
         " (RMS " + Short(d.rms) + ") over " + argument + " in [" + Bound(d.from) + ", " +
         Bound(d.to) + "]";
}

}  // namespace

void ApplyConversion(const DeGrooteConversion& converted, bool compliant, ImportedMuscle& muscle) {
  DeGrooteParams& d = muscle.params.degroote2016;
  d.active_force_width_scale = converted.active_force_width_scale;
  d.passive_fiber_strain_at_one_norm_force = converted.passive_fiber_strain_at_one_norm_force;
  muscle.conversion.push_back("active force-length: De Groote's with width scale " +
                              Short(converted.active_force_width_scale) + " (least squares), " +
                              Departure(converted.active, "l~"));
  muscle.conversion.push_back(
      "passive force-length: De Groote's with the file's strain at one norm force, " +
      FormatNumber(converted.passive_fiber_strain_at_one_norm_force) + ", " +
      Departure(converted.passive, "l~"));
  muscle.conversion.push_back("force-velocity: De Groote's with the file's v_max, shortening " +
                              Departure(converted.shortening, "v~") + ", lengthening " +
                              Departure(converted.lengthening, "v~") + " (v~ > 0 lengthening)");
  if (compliant) {
    muscle.conversion.push_back(
        "tendon force-length: De Groote's with the file's strain at one norm force, " +
        FormatNumber(converted.tendon_strain_at_one_norm_force) + ", " +
        Departure(converted.tendon, "strain"));
  }
}

}  // namespace musclesim
