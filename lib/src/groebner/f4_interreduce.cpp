#include "f4_interreduce.hpp"

#include "f4_matrix.hpp"
#include "f4_row_echelon.hpp"
#include "macaulay_rows.hpp"

namespace implicitizer::detail {

namespace {

constexpr const char* kWhere = "F4 interreduction";

}  // namespace

std::vector<ModPolynomial> reduce_basis_by_matrix(const Ring& ring, const ModularArithmetic& arithmetic,
                                                  std::vector<ModPolynomial> basis, const Budget& budget) {
  const std::vector<ModPolynomial> minimal = arithmetic.minimal_basis(std::move(basis));
  const std::size_t w = ring.monomial_size();
  std::vector<BasicReducer<ModPolynomial>> reducers;
  for (const auto& g : minimal) reducers.push_back({&g, ring.divisor_mask(g.monomials.data()), 0});
  RowCollector<ModPolynomial> collector(ring, minimal, budget, kWhere);
  const std::vector<std::int32_t> one(w, 0);
  std::vector<std::size_t> element_rows;
  for (std::size_t i = 0; i < minimal.size(); ++i) element_rows.push_back(collector.add(i, one.data()));
  collector.add_reducers(reducers);

  const MatrixColumns columns = number_columns(ring, collector.table());
  const std::vector<std::int64_t> shortest = shortest_rows_by_lead(collector.rows(), collector.table().size());
  std::vector<MatrixRow> rows;
  rows.reserve(collector.rows().size());
  for (const PendingRow& pending : collector.rows()) {
    rows.push_back(numbered_row(pending, columns.of_id));
    rows.back().coefficients = minimal[pending.poly].coefficients.data();
  }
  std::vector<const MatrixRow*> pivot(columns.of_id.size(), nullptr);
  for (std::size_t id = 0; id < shortest.size(); ++id) {
    if (shortest[id] >= 0) pivot[columns.of_id[id]] = &rows[static_cast<std::size_t>(shortest[id])];
  }

  std::vector<std::uint64_t> acc(columns.of_id.size(), 0);
  std::vector<ModPolynomial> reduced;
  reduced.reserve(minimal.size());
  for (std::size_t i = 0; i < minimal.size(); ++i) {
    budget.check(kWhere);
    const MatrixRow out = reduce_tail(rows[element_rows[i]], pivot, acc, arithmetic.modulus());
    budget.charge_work(kWorkPerStep + kWorkPerModularTerm * out.size(), kWhere);
    budget.check_terms(out.size(), kWhere);
    reduced.push_back(row_polynomial(out, columns.monomials, w));
  }
  return reduced;
}

}  // namespace implicitizer::detail
