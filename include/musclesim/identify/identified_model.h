// The `model:` block that `musclesim identify` prints for curves (docs/guide/identification.md):
// each part the data determined, with its standard errors and RMSE in comments, or the part's
// neutral stand-in with the reason. Shared by the command and the Python module, so that both
// write the same block for the same data.
#pragma once

#include <optional>
#include <string>

#include "musclesim/io/writers/model_yaml_writer.h"
#include "musclesim/identify/identify.h"

namespace musclesim {

// The block's draft (FormatModelYaml writes it). `source` says what the curves came from: the
// header's first line is "identified by musclesim identify from <source>". A part without its
// identification (nullopt) gets the stand-in of StandInModelParams(). f_iso comes from the
// active fit when there is one, else from the velocity fit. epsilon is 1e-3 times the smaller
// identified v_max; an eccentric branch whose estimates break the model's rules (Validate) is
// left out, with the rule in a comment.
ModelYamlDraft DraftIdentifiedModel(const std::string& source,
                                    const std::optional<PassiveIdentification>& passive,
                                    const std::optional<ActiveIdentification>& active,
                                    const std::optional<VelocityIdentification>& velocity);

}  // namespace musclesim
