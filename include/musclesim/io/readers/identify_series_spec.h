// The data file of `musclesim identify` on time series (docs/guide/identification.md): a
// scenario holding the experiment's known inputs, the measured series, and the parameters to
// estimate, read and validated into plain structs. A data file with a top-level `scenario`
// key is of this kind; one without is the measured curves' (io/readers/identify_spec.h).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/part_fields.h"
#include "musclesim/io/readers/document.h"

namespace musclesim {

struct SeriesSpec {
  std::optional<std::string> csv;  // path, relative to the working directory [-]; none: only
                                   // --design, which then takes its columns from `noise`
  InputPlace csv_at;               // where the data file names the csv (d.yaml:4:10) [-]
  // the standard deviation of each column's noise, by column name, in the file's order
  // [the column's unit], > 0
  std::vector<std::pair<std::string, double>> noise;
  InputPlace at;  // where the series starts in the data file [-]
};

struct SeriesParameterSpec {
  std::string path;             // a dotted path as `--set` takes it (model.f_iso) [-]
  std::optional<double> start;  // [the parameter's unit]; none: the scenario's value
  std::optional<double> lower;  // [the parameter's unit], < upper; both or neither
  std::optional<double> upper;  // [the parameter's unit]
  InputPlace at;                // where the entry is in the data file [-]
};

struct IdentifySeriesSpec {
  std::string source;    // the data file's path, for messages [-]
  std::string scenario;  // path, relative to the working directory [-]
  InputPlace scenario_at;
  std::vector<SeriesSpec> series;               // at least one
  std::vector<SeriesParameterSpec> parameters;  // at least one, paths distinct
};

// The data file's keys described once (core/part_fields.h): the file's own (`scenario`; its
// `series` and `parameters`, lists of the entries below), a series' (`csv`; its `noise`, a map
// from column names to standard deviations, has its reader's rules) and a parameter's (`path`,
// `start`, `bounds`). The rules between keys stay the reader's: a series gives csv or noise,
// bounds lower < upper with start within them, each path once.
const std::vector<PartVariant<IdentifySeriesSpec>>& IdentifySeriesFile();
const std::vector<PartVariant<SeriesSpec>>& SeriesEntry();
const std::vector<PartVariant<SeriesParameterSpec>>& SeriesParameterEntry();

// Whether the data file at `path` is of the time-series kind: a map with a top-level
// `scenario` key. Throws InputError for a file that cannot be read or parsed.
bool IsIdentifySeriesFile(const std::string& path);

// Where the measured values of the series come from.
enum class SeriesValues {
  kCsvFiles,  // each series names its csv (or, for --design only, gives its noise alone)
  kInMemory,  // the caller holds them (MeasuredSeriesFromColumns, studies/
              // identify_series_columns.h): an entry has no csv key, and may be {} (no noise)
};

// Reads and validates a data file; paths in it are relative to it. Throws InputError naming
// file:line:column, key, value and rule: an unknown key, a missing scenario, series or
// parameters, an empty list, a series with neither csv nor noise, a noise level not > 0 or
// not finite, a malformed or repeated parameter path, bounds that are not two finite numbers
// lower < upper, a start outside them.
IdentifySeriesSpec LoadIdentifySeriesSpec(const std::string& path);

// LoadIdentifySeriesSpec on `text` held in memory (the Python module writes a dict as JSON,
// which is YAML): the same reader and rules, `source` naming the text in messages in place of
// a file ("identify_series:7:5"), and the scenario's and the csv files' paths taken
// relative to `base_dir` ("": as they are).
IdentifySeriesSpec ParseIdentifySeriesSpec(const std::string& source, const std::string& text,
                                           const std::string& base_dir,
                                           SeriesValues values = SeriesValues::kCsvFiles);

// The same for a document built in code (io/readers/document.h: the Python module's dict), `name`
// naming it in messages.
IdentifySeriesSpec ReadIdentifySeriesSpec(const Document& document, const std::string& name,
                                          const std::string& base_dir,
                                          SeriesValues values = SeriesValues::kCsvFiles);

}  // namespace musclesim
