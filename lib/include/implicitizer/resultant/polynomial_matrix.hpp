#pragma once
/// \file
/// A small dense matrix of polynomials of one ring: the Sylvester matrix and its
/// reference determinant. Deliberately plain (row-major storage, no arithmetic):
/// the matrices here have a few dozen rows, and every algorithm that needs more
/// (pencil_determinant) works on its own representation.

#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// A rows × cols matrix of polynomials, all in one ring. Invariant: every entry's
/// ring equals ring() (set() enforces it), so that entries can be added and
/// multiplied without checks.
class PolynomialMatrix {
 public:
  /// The zero matrix of `rows` × `cols` entries in `ring`.
  PolynomialMatrix(RingPtr ring, std::size_t rows, std::size_t cols)
      : ring_(std::move(ring)), rows_(rows), cols_(cols), entries_(rows * cols, Polynomial(ring_)) {}

  /// The ring of every entry.
  const RingPtr& ring() const { return ring_; }
  /// The number of rows.
  std::size_t rows() const { return rows_; }
  /// The number of columns.
  std::size_t cols() const { return cols_; }
  /// Whether rows() == cols().
  bool is_square() const { return rows_ == cols_; }

  /// Entry (row, col); throws std::out_of_range outside the matrix.
  const Polynomial& at(std::size_t row, std::size_t col) const { return entries_[index(row, col)]; }
  /// Sets entry (row, col) to `value`; throws std::out_of_range outside the matrix and
  /// std::invalid_argument when `value` lives in another ring.
  void set(std::size_t row, std::size_t col, Polynomial value) {
    if (!(*value.ring() == *ring_)) throw std::invalid_argument("PolynomialMatrix::set: entry from another ring");
    entries_[index(row, col)] = std::move(value);
  }
  /// Exchanges rows `a` and `b` (fraction-free elimination pivots with it).
  void swap_rows(std::size_t a, std::size_t b) {
    for (std::size_t j = 0; j < cols_; ++j) std::swap(entries_[index(a, j)], entries_[index(b, j)]);
  }

  /// Entry-wise equality (matrices of equal rings and shapes).
  bool operator==(const PolynomialMatrix& other) const {
    return rows_ == other.rows_ && cols_ == other.cols_ && entries_ == other.entries_;
  }

 private:
  std::size_t index(std::size_t row, std::size_t col) const {
    if (row >= rows_ || col >= cols_) throw std::out_of_range("PolynomialMatrix: index outside the matrix");
    return row * cols_ + col;
  }

  RingPtr ring_;
  std::size_t rows_;
  std::size_t cols_;
  std::vector<Polynomial> entries_;
};

}  // namespace implicitizer
