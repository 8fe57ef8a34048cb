// A network's run as CSV (whole, or streamed row by row as the run records it). Columns, in
// this order:
//   t
//   for every node, in node order:        <node>.position, <node>.velocity
//   for every element, in element order:  <element>.length, <element>.tension, and for an
//                                         actuator right after them <name>.shortening_velocity,
//                                         <name>.activation, <name>.excitation (only with
//                                         activation dynamics), <name>.tension_passive,
//                                         <name>.tension_active, <name>.phase
//   for every free node, in node order:   <node>.load (the sum of the loads on it)
//   for every controller, in order:       <controller>.reference, <controller>.measured,
//                                         <controller>.error (reference - measured),
//                                         <controller>.output (NetworkSample's
//                                         ControllerSample: units of the measured quantity,
//                                         the output [-])
// Numbers have 17 significant digits and `phase` is classified as the single actuator's CSV
// does (io/trajectory_csv.h), each actuator with its own tolerance.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/io/output_file.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// The columns of `system`'s CSV, in order.
std::vector<std::string> NetworkCsvColumns(const NetworkSystem& system);

// How one network's rows are written. `phase_tolerance` is v_tol [m/s] for every actuator's
// phase (output.phase_tolerance); nullopt gives each actuator its own model's velocity
// epsilon. Keeps no reference to `system`.
class NetworkCsvFormat {
 public:
  NetworkCsvFormat(const NetworkSystem& system, std::optional<double> phase_tolerance);

  // The header line, without its newline.
  const std::string& header() const { return header_; }
  // Appends the row (with its newline) of the sample `sample` at time `t` [s].
  void AppendRow(std::string& csv, double t, const NetworkSample& sample) const;

 private:
  std::string header_;
  std::vector<double> phase_tolerance_;  // per element [m/s]; negative: not an actuator
  std::vector<bool> excitation_;         // per element: an excitation column
  std::vector<int> free_nodes_;          // node indices, in node order
};

// The header and one row per recorded point of `result`.
std::string FormatNetworkCsv(const NetworkSystem& system, const NetworkRunResult& result,
                             std::optional<double> phase_tolerance);

// Streams a run's CSV into `output` as the simulation records it: the header at once, rows
// in blocks of about 64 KiB, so that memory does not grow with the run's length. Flush()
// before committing the output.
class NetworkCsvWriter final : public NetworkSink {
 public:
  NetworkCsvWriter(StreamedOutput& output, const NetworkSystem& system,
                   std::optional<double> phase_tolerance);
  void Record(double t, const NetworkSample& sample) override;
  void Flush();

  long rows() const { return rows_; }

 private:
  StreamedOutput& output_;
  NetworkCsvFormat format_;
  std::string buffer_;
  long rows_ = 0;
};

}  // namespace musclesim
