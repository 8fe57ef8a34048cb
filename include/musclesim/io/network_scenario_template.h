// A network scenario file read and parsed once, from which many network scenarios are made by
// overrides (a sweep's points): the network counterpart of ScenarioTemplate (io/scenario.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "musclesim/io/network_scenario.h"

namespace musclesim {

// Not shared between threads: each thread makes its own Copy().
class NetworkScenarioTemplate {
 public:
  // Throws InputError if the file cannot be read or is not YAML.
  explicit NetworkScenarioTemplate(const std::string& path);
  ~NetworkScenarioTemplate();
  NetworkScenarioTemplate(const NetworkScenarioTemplate&) = delete;
  NetworkScenarioTemplate& operator=(const NetworkScenarioTemplate&) = delete;

  // An independent template parsed from the same text.
  std::unique_ptr<NetworkScenarioTemplate> Copy() const;

  // The network scenario with `overrides` ("elements[0].activation.value=0.5") applied,
  // validated as LoadNetworkScenario does (InputError naming file:line:column or --set).
  NetworkScenarioSpec Instantiate(const std::vector<std::string>& overrides) const;
  const std::string& path() const { return path_; }

 private:
  NetworkScenarioTemplate(std::string path, std::string text);
  std::string path_;
  std::string text_;
  struct Parsed;  // the document, kept out of this header (yaml-cpp is private to io)
  std::unique_ptr<Parsed> parsed_;
};

}  // namespace musclesim
