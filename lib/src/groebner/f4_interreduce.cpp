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

  const std::vector<std::uint32_t> order = ids_in_decreasing_order(ring, collector.table());
  std::vector<std::uint32_t> column_of(order.size());
  for (std::size_t c = 0; c < order.size(); ++c) column_of[order[c]] = static_cast<std::uint32_t>(c);
  std::vector<MatrixRow> rows(collector.rows().size());
  std::vector<const MatrixRow*> pivot(order.size(), nullptr);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const PendingRow& pending = collector.rows()[r];
    MatrixRow& row = rows[r];
    row.poly = pending.poly;
    row.coefficients = minimal[pending.poly].coefficients.data();
    // Multiplying by a monomial keeps the order: the columns come out increasing.
    for (const std::uint32_t id : pending.ids) row.columns.push_back(column_of[id]);
    const MatrixRow*& p = pivot[row.lead()];
    if (p == nullptr || p->size() > row.size()) p = &row;
  }

  std::vector<std::uint64_t> acc(order.size(), 0);
  std::vector<ModPolynomial> reduced;
  reduced.reserve(minimal.size());
  for (std::size_t i = 0; i < minimal.size(); ++i) {
    budget.check(kWhere);
    const MatrixRow out = reduce_tail(rows[element_rows[i]], pivot, acc, arithmetic.modulus());
    budget.charge_work(kWorkPerStep + kWorkPerModularTerm * out.size(), kWhere);
    budget.check_terms(out.size(), kWhere);
    ModPolynomial g;
    g.coefficients = out.owned;
    g.monomials.reserve(out.size() * w);
    for (const std::uint32_t c : out.columns) {
      const std::int32_t* m = collector.table().monomial(order[c]);
      g.monomials.insert(g.monomials.end(), m, m + w);
    }
    reduced.push_back(std::move(g));
  }
  return reduced;
}

}  // namespace implicitizer::detail
