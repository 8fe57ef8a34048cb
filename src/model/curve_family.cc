#include "musclesim/model/curve_family.h"

namespace musclesim {

const char* ToString(CurveFamily family) {
  switch (family) {
    case CurveFamily::kPaper: return "paper";
    case CurveFamily::kDeGroote2016: return "degroote2016";
    case CurveFamily::kMujoco: return "mujoco";
  }
  return "paper";
}

std::optional<CurveFamily> ParseCurveFamily(std::string_view text) {
  for (CurveFamily f : {CurveFamily::kPaper, CurveFamily::kDeGroote2016, CurveFamily::kMujoco}) {
    if (text == ToString(f)) return f;
  }
  return std::nullopt;
}

}  // namespace musclesim
