// A square sparse matrix written column after column, each column's rows in increasing order:
// Eigen's compressed form directly, without the sort and the row-major copy of setFromTriplets.
// The reference builds its KKT systems and Delassus blocks this way (active_set.cpp,
// reference_solver.cpp).
#pragma once

#include <algorithm>
#include <vector>

#include <Eigen/SparseCore>

namespace impulse2d {

class CompressedColumns {
 public:
  /// `entries`: how many the columns will hold, at most.
  CompressedColumns(int size, size_t entries) : size_(size) {
    outer_.reserve(static_cast<size_t>(size) + 1);
    outer_.push_back(0);
    inner_.reserve(entries);
    values_.reserve(entries);
  }
  /// The next entry of the column being written; rows must increase within a column.
  void add(int row, double value) {
    inner_.push_back(row);
    values_.push_back(value);
  }
  /// Ends the column being written; the next add starts the next column.
  void close() { outer_.push_back(static_cast<int>(inner_.size())); }
  /// The matrix, once all `size` columns are closed.
  Eigen::SparseMatrix<double> matrix() const {
    Eigen::SparseMatrix<double> matrix(size_, size_);
    matrix.resizeNonZeros(static_cast<Eigen::Index>(inner_.size()));
    std::copy(outer_.begin(), outer_.end(), matrix.outerIndexPtr());
    std::copy(inner_.begin(), inner_.end(), matrix.innerIndexPtr());
    std::copy(values_.begin(), values_.end(), matrix.valuePtr());
    return matrix;
  }

 private:
  int size_;
  std::vector<int> outer_;
  std::vector<int> inner_;
  std::vector<double> values_;
};

}  // namespace impulse2d
