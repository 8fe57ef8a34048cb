// Reads the data file of `musclesim identify`: its blocks as described (identify_spec_fields.cc).
#include <filesystem>

#include "io/readers/part_fields_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/io/readers/identify_spec.h"

namespace musclesim {

namespace {

// Where the data file names each block's CSV, in the order of IdentifyDataBlocks(), each of
// whose blocks has its `csv` as its one text (a block added there needs its place here).
constexpr InputPlace IdentifySpec::*kCsvPlaces[] = {
    &IdentifySpec::passive_csv_at, &IdentifySpec::active_csv_at, &IdentifySpec::velocity_csv_at};

}  // namespace

IdentifySpec LoadIdentifySpec(const std::string& path) {
  const Document& root = yaml::LoadFile(path);
  const yaml::Source src{path};
  const std::vector<PartVariant<IdentifySpec>>& blocks = IdentifyDataBlocks();
  std::vector<std::string> keys;
  for (const PartVariant<IdentifySpec>& block : blocks) keys.emplace_back(block.type);
  yaml::RequireMap(src, root, "", keys);
  if (root.size() == 0) {
    yaml::Fail(src, root, "", "{}", "give at least one of passive, active, velocity");
  }
  IdentifySpec spec;
  spec.source = path;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const PartVariant<IdentifySpec>& block = blocks[b];
    const Document& node = root[block.type];
    if (!node) continue;
    std::vector<std::string> block_keys;
    AddVariantKeys(block, block_keys);
    yaml::RequireMap(src, node, block.type, block_keys);
    ReadFields(src, node, block.type, block, spec);
    // its CSV relative to the data file, and where the data file names it
    const TextField<IdentifySpec>& csv = block.texts.front();
    spec.*kCsvPlaces[b] = yaml::Place(src, node[csv.key]);
    csv.set(
        spec,
        (std::filesystem::path(path).parent_path() / csv.get(spec)).lexically_normal().string());
  }
  return spec;
}

}  // namespace musclesim
