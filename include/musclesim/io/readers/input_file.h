// Reading an input file whole, as every reader of musclesim does: a regular file within a
// size limit. Anything else is refused before a byte is read, with its path and what it is:
// a FIFO would block until a writer came, a device such as /dev/zero never ends, and a
// directory holds no text.
#pragma once

#include <cstddef>
#include <string>

namespace musclesim {

// The largest input file read [bytes]: far above any scenario or data file (a table of 5
// million points, the most a waveform may have, is about 150 MiB).
inline constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

// The text of the regular file at `path`, `kind` naming what it should be in messages ("a
// YAML file", "a CSV file"). Throws InputError when the path does not exist or cannot be
// opened, is a directory, a FIFO, a socket or a device, or holds more than `max_bytes`.
std::string ReadInputFile(const std::string& path, const std::string& kind,
                          std::size_t max_bytes = kMaxInputBytes);

}  // namespace musclesim
