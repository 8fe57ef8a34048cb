// Reading a `model:` block given as text or as a document rather than as a file: for callers
// that hold the block in memory (the Python module's dict, as a document). The same reader and
// the same rules as LoadModelSpec, so a block is accepted or refused alike either way.
#pragma once

#include <string>

#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/model_yaml.h"

namespace musclesim {

// Parses `text`, the value of a `model` key (a map of f_iso, passive, active_length,
// velocity), and reads it as a scenario's model block: a fit it asks for is run. Throws
// InputError naming `source` (in place of a file name):line:column, the key path
// ("model.velocity.n"), the value and the rule broken.
ModelSpec ParseModelSpec(const std::string& source, const std::string& text);

// A model block built in code as a document (io/readers/document.h: the Python module's dict), read
// as a file's `model:` block; `source` names it in messages.
ModelSpec ReadModelSpec(const Document& block, const std::string& source);

}  // namespace musclesim
