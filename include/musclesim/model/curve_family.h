// Which curves a model block evaluates (docs/model.md section 14.1): the paper's (sections
// 2-5, the default), De Groote et al. 2016 as OpenSim implements them, or MuJoCo's muscle.
#pragma once

#include <optional>
#include <string_view>

namespace musclesim {

enum class CurveFamily { kPaper, kDeGroote2016, kMujoco };

// "paper", "degroote2016", "mujoco".
const char* ToString(CurveFamily family);

// nullopt for any other text.
std::optional<CurveFamily> ParseCurveFamily(std::string_view text);

}  // namespace musclesim
