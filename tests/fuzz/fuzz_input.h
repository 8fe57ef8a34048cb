// Shared by the libFuzzer targets of tests/fuzz: each writes its input to a file in a
// directory of its own and calls one reader on it. InputError and ParameterError are the
// expected outcome of bad input; any other exception escapes to libFuzzer, which reports it
// as a finding, as it does a crash or a sanitizer report.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "musclesim/core/errors.h"

namespace musclesim::fuzz {

// A directory for this process's files (under TMPDIR): fuzzers may run side by side.
inline const std::filesystem::path& WorkDirectory() {
  static const std::filesystem::path dir = [] {
    auto path =
        std::filesystem::temp_directory_path() / ("musclesim_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return dir;
}

// Writes the fuzz input to WorkDirectory()/name and returns the path.
inline std::string WriteInput(const std::uint8_t* data, std::size_t size, const char* name) {
  const std::string path = (WorkDirectory() / name).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

// Copies the shipped scenarios into WorkDirectory(), so that a file naming a `base`
// (antagonist_move.yaml, concentric.yaml, ...) finds it beside the input.
inline void CopyShippedScenarios() {
  namespace fs = std::filesystem;
  for (const auto& entry : fs::directory_iterator(MUSCLESIM_SOURCE_DIR "/scenarios")) {
    fs::copy_file(entry.path(), WorkDirectory() / entry.path().filename(),
                  fs::copy_options::overwrite_existing);
  }
}

// Runs `read`; an InputError or ParameterError is bad input correctly refused.
template <typename Read>
void ExpectOnlyInputErrors(Read read) {
  try {
    read();
  } catch (const InputError&) {
  } catch (const ParameterError&) {}
}

}  // namespace musclesim::fuzz
