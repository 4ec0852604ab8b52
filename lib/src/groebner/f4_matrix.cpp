#include "f4_matrix.hpp"

#include <algorithm>

namespace implicitizer::detail {

namespace {

constexpr const char* kWhere = "F4 symbolic preprocessing";

// Splits the rows into pivots (per leading column the shortest row) and rows to
// reduce.
void split_rows(const std::vector<PendingRow>& pending, std::size_t ids, const std::vector<std::uint32_t>& column_of,
                const std::vector<ModPolynomial>& basis, MacaulayMatrix& matrix) {
  const std::vector<std::int64_t> pivot_row = shortest_rows_by_lead(pending, ids);
  for (std::size_t r = 0; r < pending.size(); ++r) {
    MatrixRow row = numbered_row(pending[r], column_of);
    row.coefficients = basis[row.poly].coefficients.data();
    const bool pivot = pivot_row[pending[r].ids.front()] == static_cast<std::int64_t>(r);
    (pivot ? matrix.pivots : matrix.to_reduce).push_back(std::move(row));
  }
}

}  // namespace

MacaulayMatrix build_macaulay_matrix(const Ring& ring, const std::vector<ModPolynomial>& basis,
                                     const std::vector<BasicReducer<ModPolynomial>>& reducers,
                                     const std::vector<SelectedPair>& pairs, const Budget& budget) {
  const std::size_t w = ring.monomial_size();
  RowCollector<ModPolynomial> collector(ring, basis, budget, kWhere);
  std::vector<std::int32_t> lcm(w), shift(w);
  for (const SelectedPair& pair : pairs) {
    const ModPolynomial& f = basis[pair.first];
    const ModPolynomial& g = basis[pair.second];
    ring.lcm(f.monomials.data(), g.monomials.data(), lcm.data());
    ring.divide(lcm.data(), f.monomials.data(), shift.data());
    collector.add(pair.first, shift.data());
    ring.divide(lcm.data(), g.monomials.data(), shift.data());
    collector.add(pair.second, shift.data());
  }
  collector.add_reducers(reducers);
  MatrixColumns columns = number_columns(ring, collector.table());
  MacaulayMatrix matrix;
  matrix.columns = columns.of_id.size();
  matrix.column_monomials = std::move(columns.monomials);
  split_rows(collector.rows(), collector.table().size(), columns.of_id, basis, matrix);
  return matrix;
}

MatrixRow numbered_row(const PendingRow& pending, const std::vector<std::uint32_t>& column_of) {
  MatrixRow row;
  row.poly = pending.poly;
  row.columns.reserve(pending.ids.size());
  // Multiplying by a monomial keeps the order: the columns come out increasing.
  for (const std::uint32_t id : pending.ids) row.columns.push_back(column_of[id]);
  return row;
}

ModPolynomial row_polynomial(const MatrixRow& row, const std::vector<std::int32_t>& column_monomials,
                             std::size_t width) {
  ModPolynomial g;
  g.coefficients = row.owned;
  g.monomials.reserve(row.size() * width);
  for (const std::uint32_t c : row.columns) {
    const std::int32_t* m = column_monomials.data() + std::size_t{c} * width;
    g.monomials.insert(g.monomials.end(), m, m + width);
  }
  return g;
}

}  // namespace implicitizer::detail
