// The reference tables in the docs are the parts' descriptions as they are: each table, between
// its markers, is what ReferenceTable renders; and the descriptions' ranges are the ones the
// readers apply (a value past each bound refused with that bound's rule, the default used when
// the key is absent).
#include "musclesim/io/writers/reference_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/activation_families.h"
#include "musclesim/dynamics/controller_gains.h"
#include "musclesim/dynamics/element_laws.h"
#include "musclesim/dynamics/load_kinds.h"
#include "musclesim/dynamics/waveform_shapes.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/model_text.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/model/family_fields.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

std::string Read(const std::string& relative) {
  std::ifstream in(std::string(MUSCLESIM_SOURCE_DIR) + "/" + relative);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text between "<!-- reference: NAME -->\n" and "<!-- end reference -->" in `page`.
std::string Block(const std::string& page, const std::string& name) {
  const std::string open = "<!-- reference: " + name + " -->\n";
  const std::size_t begin = page.find(open);
  if (begin == std::string::npos) return "(no block " + name + ")";
  const std::size_t end = page.find("<!-- end reference -->", begin);
  return page.substr(begin + open.size(), end - begin - open.size());
}

constexpr const char* kRewrite =
    "the docs' table differs from the part's description: python3 scripts/reference_tables.py "
    "rewrites it";

TEST(ReferenceTable, ElementLawsInTheNetworksGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/networks.md"), "element laws"), ReferenceTable(ElementLaws()))
      << kRewrite;
}

TEST(ReferenceTable, LoadsInTheScenariosGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "loads"), ReferenceTable(LoadVariants()))
      << kRewrite;
}

TEST(ReferenceTable, ActivationFamiliesInTheScenariosGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "activation dynamics"),
            ReferenceTable(ActivationFamilies(), "family"))
      << kRewrite;
}

TEST(ReferenceTable, WaveformShapesInTheScenariosGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/scenarios.md"), "waveforms"), ReferenceTable(WaveformShapes()))
      << kRewrite;
}

TEST(ReferenceTable, ModelFamiliesInTheModelGuideAreTheDescriptions) {
  EXPECT_EQ(Block(Read("docs/guide/model.md"), "model families"),
            ReferenceTable(ModelFamilies(), "family"))
      << kRewrite;
}

TEST(ReferenceTable, GainsInTheControlGuideAreTheDescription) {
  EXPECT_EQ(Block(Read("docs/guide/control.md"), "gains"), ReferenceTable(ControllerGains()))
      << kRewrite;
}

TEST(ReferenceTable, RendersEachFieldOnceWithItsDefaultAndBounds) {
  const std::string table = ReferenceTable(LoadVariants());
  EXPECT_THAT(table, HasSubstr("| `mass` (hanging mass) | F = mass gravity"));
  EXPECT_THAT(table, HasSubstr("| `gravity` | m/s^2 | 9.81 | from -1000 to 1000: about 100 g"));
  EXPECT_THAT(table, HasSubstr("| `stiffness` | N/m | required | from 0 to 1e+12: "));
}

// A network with one element written as `element` (a map's inner text), read from memory.
std::string ElementError(const std::string& element) {
  const std::string text =
      "nodes:\n  - {name: wall, fixed: 0.0}\n  - {name: load, mass: 1.0, position: 0.1}\n"
      "elements:\n  - {name: e, from: wall, to: load, " +
      element + "}\ntime: {start: 0.0, end: 0.1}\n";
  try {
    ReadScenario(ParseDocument("net.yaml", text), "net.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  return "(read)";
}

// Every field of every law: its value just past each bound is refused with the bound's rule,
// by the reader, at its key path; a default applies when the key is absent.
TEST(ReferenceTable, TheReaderAppliesEachLawsRanges) {
  const auto text_of = [](const ElementLaw& law, const ElementField& changed, double value) {
    std::string keys = std::string("type: ") + law.type;
    std::string nested;  // "exponential: {k: 1, alpha: 2}"
    std::string head;
    for (const ElementField& field : law.fields) {
      const double v = &field == &changed ? value : field.range.max / 2.0;
      const std::string key = field.key;
      const std::string number = FormatNumber(v);
      if (key.find('.') == std::string::npos) {
        keys += ", " + key + ": " + number;
        continue;
      }
      const std::string h(HeadKey(key));
      if (h != head) {
        if (!nested.empty()) keys += ", " + nested + "}";
        nested = h + ": {";
        head = h;
      } else {
        nested += ", ";
      }
      nested += key.substr(h.size() + 1) + ": " + number;
    }
    if (!nested.empty()) keys += ", " + nested + "}";
    return keys;
  };
  for (const ElementLaw& law : ElementLaws()) {
    for (const ElementField& field : law.fields) {
      SCOPED_TRACE(std::string(law.name) + " " + field.key);
      const double past_max = field.range.max * 2.0;
      const double below_min = field.range.min_exclusive ? field.range.min : field.range.min - 1.0;
      for (const double bad : {past_max, below_min}) {
        const std::string message = ElementError(text_of(law, field, bad));
        EXPECT_THAT(message, HasSubstr("elements[0]." + std::string(field.key) + " = "));
        EXPECT_THAT(message, HasSubstr(field.range.Rule()));
      }
      EXPECT_EQ(ElementError(text_of(law, field, field.range.max)), "(read)");
    }
  }
}

// The same for the other families' model blocks: each ranged field past each bound refused
// with its rule at model.KEY, and its largest value read.
TEST(ReferenceTable, TheReaderAppliesEachModelFamilysRanges) {
  // what each family requires, in order; the field under test replaces or joins them
  const auto required = [](const ModelFamily& family) {
    return std::string_view(family.type) == "mujoco"
               ? std::vector<std::pair<std::string, std::string>>{{"f_iso", "100"},
                                                                  {"lengthrange", "[0.1, 0.2]"}}
               : std::vector<std::pair<std::string, std::string>>{{"f_iso", "100"},
                                                                  {"optimal_fiber_length", "0.1"}};
  };
  const auto error = [](const std::string& text) {
    try {
      ParseModelSpec("model.yaml", text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(read)");
  };
  for (const ModelFamily& family : ModelFamilies()) {
    for (const NumberField<ModelParams>& field : family.fields) {
      if (field.values != FieldValues::kRange) continue;
      SCOPED_TRACE(std::string(family.type) + " " + field.key);
      const auto text = [&](double value) {
        auto fields = required(family);
        bool replaced = false;
        for (auto& [key, given] : fields) {
          if (key == field.key) given = FormatNumber(value), replaced = true;
        }
        if (!replaced) fields.emplace_back(field.key, FormatNumber(value));
        std::string block = std::string("{family: ") + family.type;
        for (const auto& [key, given] : fields) block += ", " + key + ": " + given;
        return block + "}";
      };
      const double below = field.range.min_exclusive ? field.range.min : field.range.min - 1.0;
      for (const double bad : {field.range.max * 2.0, below}) {
        const std::string message = error(text(bad));
        EXPECT_THAT(message, HasSubstr("model." + std::string(field.key) + " = "));
        EXPECT_THAT(message, HasSubstr(field.range.Rule()));
      }
      EXPECT_EQ(error(text(field.range.max)), "(read)");
    }
  }
}

}  // namespace
}  // namespace musclesim
