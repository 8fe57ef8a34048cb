#include "run_roots.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include "musclesim/core/errors.h"

namespace musclesim {

std::vector<Root> RootsOf(const NetworkSystem& system, const NetworkRunRequest& request,
                          const double* y) {
  std::vector<Root> roots;
  for (std::size_t k = 0; k < system.kinks().size(); ++k) {
    roots.push_back({Root::kKink, static_cast<int>(k), 0.0});
  }
  for (std::size_t i = 0; i < request.limits.size(); ++i) {
    const LengthLimit& limit = request.limits[i];
    const std::string path = "limits[" + std::to_string(i) + "].";
    const int e = system.FindElement(limit.element);
    if (e < 0) {
      std::string known;
      for (const Element& element : system.elements()) {
        known.append(known.empty() ? "" : ", ").append(element.name);
      }
      throw ParameterError(path + "element", limit.element,
                           "names no element; the elements are: " + known);
    }
    const double length = system.Length(e, request.t_start, y);
    if (limit.min_length) {
      Require(std::isfinite(*limit.min_length) && *limit.min_length >= 0.0 &&
                  *limit.min_length < length,
              path + "min_length", *limit.min_length,
              "must be >= 0 and below " + limit.element +
                  "'s initial length = " + FormatNumber(length) + " [m]");
      roots.push_back({Root::kMinLength, e, *limit.min_length});
    }
    if (limit.max_length) {
      Require(std::isfinite(*limit.max_length) && *limit.max_length > length, path + "max_length",
              *limit.max_length,
              "must be above " + limit.element + "'s initial length = " + FormatNumber(length) +
                  " [m]");
      roots.push_back({Root::kMaxLength, e, *limit.max_length});
    }
  }
  if (system.dimensions() > 1) {
    for (std::size_t e = 0; e < system.elements().size(); ++e) {
      const int element = static_cast<int>(e);
      for (int k = 0; k < system.SegmentCount(element); ++k) {
        roots.push_back({Root::kShortSegment, element, NetworkSystem::kMinSegmentLength, k});
      }
    }
    return roots;
  }
  std::set<std::pair<std::string_view, std::string_view>> pairs;  // a set: a large network
  for (std::size_t e = 0; e < system.elements().size(); ++e) {
    const Element& element = system.elements()[e];
    const std::pair<std::string_view, std::string_view> ends(element.from, element.to);
    if (!pairs.insert(ends).second) continue;
    roots.push_back({Root::kZeroLength, static_cast<int>(e), 0.0});
  }
  return roots;
}

}  // namespace musclesim
