// Private: overrides (`--set KEY=VALUE` on the command line), one value of a parsed document
// replaced (or one key added to an existing map) before the document is read, so that the override
// is validated exactly as the file's own value would be. Used by both forms of a scenario file.
#pragma once

#include <string>

#include "musclesim/io/readers/document.h"

namespace musclesim::yaml {

// Applies `text` ("dotted.path=value", the path as io/key_path.h reads it) to `root`, the
// top-level map of `file` (named in messages). A block whose keys are all optional
// (model.velocity.eccentric) is created when the file leaves it out. Throws InputError when
// the text is not KEY=VALUE, the path is malformed, leads nowhere, or names a map or list.
// `label` starts each message ("--set", "axis": the caller's word for overrides).
void ApplyOverride(Document& root, const std::string& text, const std::string& file,
                   const std::string& label);
// Each of `overrides`, in order.
void ApplyOverrides(Document& root, const Overrides& overrides, const std::string& file);

}  // namespace musclesim::yaml
