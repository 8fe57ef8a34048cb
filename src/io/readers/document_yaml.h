// Private: a Document (io/readers/document.h) from the yaml-cpp tree a file parses into, and
// back as one for the YAML writers and messages: the only place the two meet.
#pragma once

#include <yaml-cpp/yaml.h>

#include "musclesim/io/readers/document.h"

namespace musclesim {

// The tree of `document`: scalars as the text a file would hold (a number's shortest exact
// form, YAML's .nan and .inf; quoted text tagged as quoted), with no file positions.
YAML::Node ToYaml(const Document& document);
// The document of `node`, with each value's and key's position; every scalar is Text as
// written. Throws InputError, placed in `file`, for an alias inside the value it names and
// for aliases that expand the tree past a million values.
Document FromYaml(const YAML::Node& node, const std::string& file);

}  // namespace musclesim
