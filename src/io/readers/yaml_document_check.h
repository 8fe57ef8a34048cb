// Private: the checks yaml-cpp does not make on a whole document, run on every file the
// program reads (yaml::Parse). yaml-cpp keeps a map's duplicate keys and answers a lookup with
// the first, so `{mass: 0.1, mass: -5}` would silently use 0.1; it also reads only the first
// of several documents. Both are refused here, before any reader looks at a value.
#pragma once

#include <string>

namespace musclesim::yaml {

// Walks the parse events of `text` (the file `path`, for messages) and throws InputError for
// a key given twice in one map (naming both places), a map key that is not a plain name (a
// list, a map, an alias or nothing), a key or value holding a control character, or a second
// document. `text` must parse: call it after YAML::Load succeeded.
void CheckDocument(const std::string& path, const std::string& text);

// The message for nesting past yaml-cpp's depth limit (YAML::DeepRecursion), `depth` levels.
std::string TooDeep(int depth);

}  // namespace musclesim::yaml
