// OpenSim's Thelen2003Muscle as family degroote2016 (docs/model.md 14.5): its closed-form
// curves (model/thelen2003.h), read with OpenSim 4.6's defaults, brought to the nearest De
// Groote muscle, each curve's departure reported.
#include <string>
#include <utility>
#include <vector>

#include "io/import/conversion_report.h"
#include "io/import/muscle_import_readers.h"
#include "io/import/osim_muscle_parts.h"
#include "io/import/osim_property_reader.h"
#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

using tinyxml2::XMLElement;

ThelenCurves ReadCurves(const OsimPropertyReader& read, const std::string& name) {
  ThelenCurves c;
  read.Read("FmaxTendonStrain", c.FmaxTendonStrain);
  read.Read("FmaxMuscleStrain", c.FmaxMuscleStrain);
  read.Read("KshapeActive", c.KshapeActive);
  read.Read("KshapePassive", c.KshapePassive);
  read.Read("Af", c.Af);
  read.Read("Flen", c.Flen);
  read.Read("fv_linear_extrap_threshold", c.fv_linear_extrap_threshold);
  try {
    Validate(c);
  } catch (const ParameterError& e) {
    throw InputError("Thelen2003Muscle (" + read.WhereOf(e.path()) + ") '" + name +
                     "': " + e.path() + " = " + e.value() + ": " + e.rule());
  }
  return c;
}

}  // namespace

ImportedMuscle ReadThelen(const XMLElement& element, const std::string& path) {
  const OsimPropertyReader read(element, path);
  ImportedMuscle muscle = StartMuscle(read, "Thelen2003Muscle");
  muscle.params.degroote2016.fiber_damping = 0.0;  // Thelen's fiber has no damping

  const ThelenCurves curves = ReadCurves(read, muscle.name);
  const bool rigid = read.Flag("ignore_tendon_compliance", false);
  ApplyConversion(NearestDeGroote(curves), !rigid, muscle);
  if (!rigid) {
    SetCompliantTendon(muscle, curves.FmaxTendonStrain, "FmaxTendonStrain",
                       read.WhereOf("FmaxTendonStrain"));
  }
  SetFirstOrderActivation(read, 0.015, 0.05, muscle);
  std::vector<std::pair<std::string, std::string>> names = kOsimPropertyNames;
  names.emplace_back("passive_fiber_strain_at_one_norm_force", "FmaxMuscleStrain (De Groote's e0)");
  ValidateImported(muscle, names);
  for (const char* flag : {"ignore_tendon_compliance", "ignore_activation_dynamics"}) {
    if (read.Flag(flag, false)) {
      muscle.notes.push_back(std::string(flag) +
                             " is true: OpenSim 4.6 does not run a Thelen2003Muscle so (\"not "
                             "currently implemented\"); the scenario follows the flag");
    }
  }
  muscle.notes.push_back(
      "Thelen's force-velocity curve scales its shortening velocity by 0.25 + 0.75 activation; "
      "it is converted at activation 1, and De Groote's v_max does not fall with activation");
  AddPennationClampNote(read, muscle);
  AddCommonNotes(read, element, muscle);
  return muscle;
}

}  // namespace musclesim
