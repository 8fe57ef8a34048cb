// musclesim._plot_columns and musclesim._plot_model: the figures of `musclesim plot` drawn
// from values in memory (plotting.py's plot() picks one by the data's type). The columns
// become the CsvTable the CLI reads from its CSV, every number as its shortest exact text
// (which reads back to the same double), so that the script, and so the figure, is the one
// the CLI makes of the CSV of the same data.
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "document.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/csv_table.h"
#include "musclesim/io/readers/model_text.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/core/number_format.h"
#include "musclesim/model/tension.h"
#include "musclesim/plot/plot.h"
#include "py_scenario.h"
#include "typed_objects.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

// One column as plotting.py hands it over: float64 numbers, or texts (phase, status, ...).
struct Column {
  bool text = false;
  std::vector<double> numbers;
  std::vector<std::string> texts;

  std::size_t size() const { return text ? texts.size() : numbers.size(); }
};

// Runs `call`; a plot option the library refuses (ParameterError naming the option, which
// plot() takes as an argument of the same name) is an InputError "NAME VALUE: rule".
template <typename Call>
void Renamed(Call call) {
  try {
    call();
  } catch (const ParameterError& e) {
    throw InputError(e.path() + " " + e.value() + ": ",
                     InputFault{std::nullopt, e.path(), e.value(), e.rule()});
  }
}

PlotOptions Options(const std::string& output, const std::string& title, int width, int height) {
  PlotOptions options;
  options.output = output;
  options.title = title;
  options.width = width;
  options.height = height;
  Renamed([&] { Validate(options); });
  return options;
}

// The columns copied out of Python (the GIL is needed only here); every column as long as
// the first.
std::vector<Column> ReadColumns(const std::vector<std::string>& names, const AnyList& given) {
  if (names.size() != py::len(given)) {
    throw std::invalid_argument("_plot_columns: as many names as columns are needed");
  }
  std::vector<Column> columns;
  for (const py::handle item : given) {
    Column column;
    if (py::isinstance<py::array>(item)) {
      const auto array =
          py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(item);
      if (!array || array.ndim() != 1) {
        throw std::invalid_argument("_plot_columns: a column must be a 1-D float64 array");
      }
      column.numbers.assign(array.data(), array.data() + array.size());
    } else {
      column.text = true;
      column.texts = item.cast<std::vector<std::string>>();
    }
    columns.push_back(std::move(column));
  }
  for (std::size_t c = 1; c < columns.size(); ++c) {
    if (columns[c].size() != columns[0].size()) {
      throw InputError("data: column " + names[c] + " has " + std::to_string(columns[c].size()) +
                       " values, but column " + names[0] + " has " +
                       std::to_string(columns[0].size()) + ": every column must be as long");
    }
  }
  return columns;
}

// The table the CLI would read from the columns' CSV. `empty_nan`: NaN as an empty field, as
// a sweep summary writes a metric a point has none of; otherwise "nan", which the figures
// refuse as not finite. A row's "line" is its 0-based index, so that messages name a cell as
// SOURCE:ROW.
CsvTable TableOf(const std::vector<std::string>& names, const std::vector<Column>& columns,
                 bool empty_nan) {
  CsvTable table;
  table.header = names;
  const std::size_t rows = columns.empty() ? 0 : columns[0].size();
  table.rows.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    std::vector<std::string>& row = table.rows[r];
    row.reserve(columns.size());
    for (const Column& column : columns) {
      if (column.text) {
        row.push_back(column.texts[r]);
      } else {
        const double value = column.numbers[r];
        row.push_back(empty_nan && std::isnan(value) ? std::string() : FormatNumber(value));
      }
    }
    table.lines.push_back(r);
  }
  return table;
}

// Writes the script first when asked, as the CLI's --script does, then renders the figure.
void Draw(const std::string& script, const PlotOptions& options,
          const std::optional<std::string>& script_path) {
  CheckOutputFiles({}, {{options.output, "output"}, {script_path.value_or(""), "script"}});
  if (script_path) WriteOutput(*script_path, script);
  Render(script, options);
}

void PlotColumns(const std::vector<std::string>& names, const AnyList& columns,
                 const std::string& output, const std::string& title, int width, int height,
                 const std::optional<std::string>& x, const std::optional<std::string>& y,
                 const std::optional<std::string>& color,
                 const std::optional<std::string>& script_path) {
  const PlotOptions options = Options(output, title, width, height);
  if (!x && (y || color)) {
    throw InputError(InputFault{std::nullopt, y ? "y" : "color", y ? *y : *color,
                                "given without x; y (a metric) and color (a swept path) go with "
                                "x, the swept path of a sweep summary, as the CLI's --y and "
                                "--color go with --x"});
  }
  const std::vector<Column> values = ReadColumns(names, columns);
  py::gil_scoped_release release;
  Renamed([&] {
    CsvTable table = TableOf(names, values, x.has_value());
    std::string script;
    if (x) {
      table.source = "sweep";
      script = SweepPlotScript(table, *x, y, color, options);
    } else {
      // the CLI's choice by the table's form: residuals, a network's run on a line or in
      // space, a single actuator's
      table.source = IsResidualTable(table) ? "residuals" : "trajectory";
      script = RunPlotScript(table, options);
    }
    Draw(script, options, script_path);
  });
}

// The frames of a run in the plane or in space, as `musclesim plot --frames/--frame-count`.
void PlotFrames(const std::vector<std::string>& names, const AnyList& columns,
                const std::string& output, const std::string& title, int width, int height,
                const std::vector<double>& times, int count, const py::object& scenario,
                const std::optional<std::string>& script_path) {
  const PlotOptions options = Options(output, title, width, height);
  const std::vector<Column> values = ReadColumns(names, columns);
  std::optional<Scenario> drawn;
  if (!scenario.is_none()) drawn = ScenarioArgument(scenario, "plot: scenario").scenario;
  py::gil_scoped_release release;
  Renamed([&] {
    CsvTable table = TableOf(names, values, false);
    table.source = "trajectory";
    const std::string flag = times.empty() ? "frame_count" : "frames";
    Draw(FramesPlotScript(table, times, count, drawn ? &*drawn : nullptr, flag, options), options,
         script_path);
  });
}

void PlotModel(const AnyDict& params, const std::string& output, const std::string& title,
               int width, int height, const std::optional<std::string>& script_path) {
  const PlotOptions options = Options(output, title, width, height);
  const Document block = DocumentFrom(params, "model");
  py::gil_scoped_release release;
  const TensionModel model(ReadModelSpec(block, "<model>").params);
  Renamed([&] { Draw(CurvesPlotScript(model, options), options, script_path); });
}

}  // namespace

void BindPlot(py::module_& m) {
  m.def("_plot_columns", &PlotColumns, py::arg("names"), py::arg("columns"), py::arg("output"),
        py::arg("title"), py::arg("width"), py::arg("height"), py::arg("x"), py::arg("y"),
        py::arg("color"), py::arg("script"),
        "The figure `musclesim plot` draws of a CSV with these columns (each a 1-D float64 "
        "array or a list of str), with the GIL released: with x a sweep summary's, else a "
        "residual table's, a network trajectory's or a trajectory's. musclesim.plot is the "
        "public way.");
  m.def("_plot_frames", &PlotFrames, py::arg("names"), py::arg("columns"), py::arg("output"),
        py::arg("title"), py::arg("width"), py::arg("height"), py::arg("times"), py::arg("count"),
        py::arg("scenario"), py::arg("script"),
        "The frames figure (`musclesim plot --frames/--frame-count`) of a run in the plane or "
        "in space given as its columns, at `times` (or `count` evenly spaced ones when empty), "
        "the elements drawn along their paths with `scenario`, with the GIL released. "
        "musclesim.plot is the public way.");
  m.def("_plot_model", &PlotModel, py::arg("params"), py::arg("output"), py::arg("title"),
        py::arg("width"), py::arg("height"), py::arg("script"),
        "The curves figure (`musclesim plot --curves`) of the model block given as a dict, "
        "with the GIL released. musclesim.plot is the public way.");
}

}  // namespace musclesim::python
