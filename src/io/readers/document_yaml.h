// Private: a Document (io/readers/document.h) as the yaml-cpp tree the readers read, and back.
#pragma once

#include <yaml-cpp/yaml.h>

#include "musclesim/io/readers/document.h"

namespace musclesim {

// The tree of `document`: scalars as the text a file would hold (a number's shortest exact
// form, YAML's .nan and .inf), with no file positions.
YAML::Node ToYaml(const Document& document);
// The document of `node`; every scalar is Text as written.
Document FromYaml(const YAML::Node& node);

}  // namespace musclesim
