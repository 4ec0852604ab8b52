#include "f4_matrix.hpp"

#include <algorithm>

namespace implicitizer::detail {

namespace {

constexpr const char* kWhere = "F4 symbolic preprocessing";

// The columns: the table's monomials in decreasing order; column_of[id].
std::vector<std::uint32_t> number_columns(const Ring& ring, const MonomialTable& table, MacaulayMatrix& matrix) {
  const std::vector<std::uint32_t> order = ids_in_decreasing_order(ring, table);
  const std::size_t w = ring.monomial_size();
  std::vector<std::uint32_t> column_of(table.size());
  matrix.columns = table.size();
  matrix.column_monomials.resize(table.size() * w);
  for (std::size_t c = 0; c < order.size(); ++c) {
    column_of[order[c]] = static_cast<std::uint32_t>(c);
    std::copy(table.monomial(order[c]), table.monomial(order[c]) + w, matrix.column_monomials.data() + c * w);
  }
  return column_of;
}

// Splits the rows into pivots (per leading column the shortest row: it costs least
// to subtract) and rows to reduce.
void split_rows(std::vector<PendingRow>& pending, const std::vector<std::uint32_t>& column_of,
                const std::vector<ModPolynomial>& basis, MacaulayMatrix& matrix) {
  std::vector<std::int64_t> pivot_of(matrix.columns, -1);  // index into `rows`
  std::vector<MatrixRow> rows(pending.size());
  for (std::size_t r = 0; r < pending.size(); ++r) {
    MatrixRow& row = rows[r];
    row.columns.resize(pending[r].ids.size());
    // Multiplying by a monomial keeps the order: the columns come out increasing.
    for (std::size_t i = 0; i < row.columns.size(); ++i) row.columns[i] = column_of[pending[r].ids[i]];
    row.poly = pending[r].poly;
    row.coefficients = basis[row.poly].coefficients.data();
    std::int64_t& p = pivot_of[row.lead()];
    if (p < 0 || rows[static_cast<std::size_t>(p)].size() > row.size()) p = static_cast<std::int64_t>(r);
  }
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const bool pivot = pivot_of[rows[r].lead()] == static_cast<std::int64_t>(r);
    (pivot ? matrix.pivots : matrix.to_reduce).push_back(std::move(rows[r]));
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
  MacaulayMatrix matrix;
  const std::vector<std::uint32_t> column_of = number_columns(ring, collector.table(), matrix);
  split_rows(collector.rows(), column_of, basis, matrix);
  return matrix;
}

}  // namespace implicitizer::detail
