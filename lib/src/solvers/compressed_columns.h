// A square sparse matrix written column after column, each column's rows in increasing order,
// straight into Eigen's compressed arrays: without the sort and the row-major copy of
// setFromTriplets, and without a copy at the end. The reference builds its active-set systems
// and Delassus blocks this way (active_set.cpp, reference_solver.cpp).
#pragma once

#include <utility>

#include <Eigen/SparseCore>

namespace impulse2d {

class CompressedColumns {
 public:
  /// `entries`: how many the columns will hold, at most.
  CompressedColumns(int size, Eigen::Index entries) : matrix_(size, size) {
    matrix_.resizeNonZeros(entries);
    matrix_.outerIndexPtr()[0] = 0;
  }
  /// The next entry of the column being written; rows must increase within a column.
  void add(int row, double value) {
    matrix_.innerIndexPtr()[count_] = row;
    matrix_.valuePtr()[count_] = value;
    ++count_;
  }
  /// Ends the column being written; the next add starts the next column.
  void close() { matrix_.outerIndexPtr()[++closed_] = static_cast<int>(count_); }
  /// The matrix, once all columns are closed; the writer is spent.
  Eigen::SparseMatrix<double> take() {
    matrix_.resizeNonZeros(count_);
    return std::move(matrix_);
  }

 private:
  Eigen::SparseMatrix<double> matrix_;
  Eigen::Index count_ = 0;
  Eigen::Index closed_ = 0;
};

}  // namespace impulse2d
