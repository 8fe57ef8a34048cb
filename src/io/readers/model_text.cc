#include "musclesim/io/readers/model_text.h"

#include "io/readers/model_yaml_node.h"

namespace musclesim {

ModelSpec ParseModelSpec(const std::string& source, const std::string& text) {
  // yaml::Parse makes the whole-document checks a file gets (duplicate keys, one document)
  return ReadModelSpec(yaml::Source{source}, yaml::Parse(source, text), "model");
}

ModelSpec ReadModelSpec(const Document& block, const std::string& source) {
  return ReadModelSpec(yaml::Source{source, source}, block, "model");
}

}  // namespace musclesim
