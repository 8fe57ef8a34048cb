// IsNetworkScenario: which of the two forms a scenario file is, from its top-level keys.
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <sstream>

#include "io/yaml_fields.h"
#include "musclesim/errors.h"
#include "musclesim/io/network_scenario.h"

namespace musclesim {

namespace {

// Walks the parse events of the first document and throws Found at a top-level key `nodes`.
// Events build no nodes, so the look costs a scan of the text, not a document's memory.
class NodesKeyFinder : public YAML::EventHandler {
 public:
  struct Found {};

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override { Item(nullptr); }
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override { Item(nullptr); }
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string& value) override {
    Item(&value);
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    Open(false);
  }
  void OnSequenceEnd() override { --depth_; }
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    Open(true);
  }
  void OnMapEnd() override { --depth_; }

 private:
  // a key or value of the top-level map when depth_ is 1; keys and values alternate
  void Item(const std::string* scalar) {
    if (depth_ != 1 || !top_is_map_) return;
    if (expecting_key_ && scalar != nullptr && *scalar == "nodes") throw Found{};
    expecting_key_ = !expecting_key_;
  }
  void Open(bool is_map) {
    if (depth_ == 0) top_is_map_ = is_map;
    Item(nullptr);  // a collection is one key or value of the map it is in
    ++depth_;
  }

  int depth_ = 0;
  bool top_is_map_ = false;
  bool expecting_key_ = true;
};

}  // namespace

bool IsNetworkScenario(const std::string& path) {
  std::istringstream stream(yaml::ReadText(path));
  YAML::Parser parser(stream);
  NodesKeyFinder finder;
  try {
    parser.HandleNextDocument(finder);
  } catch (const NodesKeyFinder::Found&) {
    return true;
  } catch (const YAML::ParserException& e) {
    throw InputError(path + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": YAML syntax error: " + e.msg);
  }
  return false;
}

}  // namespace musclesim
