// A scenario file with some of its values replaced, as text: what `musclesim identify`
// writes as the estimated scenario, a complete file that runs as the original does.
#pragma once

#include <string>
#include <vector>

#include "musclesim/io/readers/document.h"

namespace musclesim {

// The scenario at `path` (either form) with `overrides` applied (io/readers/document.h), emitted as
// YAML headed by `header` (one comment line each, "# " prepended). The original's comments are not
// kept; its maps and lists keep their block or flow style. Throws InputError for a file that cannot
// be read or parsed, or an override that does not apply (the overrides' messages). The result is
// not validated here: load it.
std::string RewriteScenario(const std::string& path, const Overrides& overrides,
                            const std::vector<std::string>& header);

// The same for a scenario `document` built in code (io/readers/document.h), `name` naming it in the
// messages of an override that does not apply.
std::string RewriteScenario(const Document& document, const std::string& name,
                            const Overrides& overrides, const std::vector<std::string>& header);

// The documents the two write: the scenario's document with `overrides` applied, in memory,
// for a caller that goes on editing it (the optimum's control tables, say).
Document RewrittenDocument(const std::string& path, const Overrides& overrides);
Document RewrittenDocument(const Document& document, const std::string& name,
                           const Overrides& overrides);

}  // namespace musclesim
