// Where a Jacobian can be nonzero: what a band or sparse linear solver needs to know of it.
#pragma once

#include <vector>

namespace musclesim {

// The structural entries of a square Jacobian in compressed-column order (by column, then
// row), each once, the whole diagonal included (the Newton matrix I - gamma J needs it).
struct JacobianPattern {
  int size = 0;                    // rows = columns
  std::vector<int> rows;           // row of entry k
  std::vector<int> column_starts;  // entries of column j: [column_starts[j], column_starts[j+1])
  int lower_bandwidth = 0;         // max(row - column) over the entries
  int upper_bandwidth = 0;         // max(column - row) over the entries

  int entries() const { return static_cast<int>(rows.size()); }
  int ColumnOf(int entry) const;  // the column of entry k (a binary search)
};

}  // namespace musclesim
