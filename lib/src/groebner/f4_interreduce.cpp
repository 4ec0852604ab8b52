#include "f4_interreduce.hpp"

#include <algorithm>

#include "f4_row_echelon.hpp"
#include "macaulay_rows.hpp"

namespace implicitizer::detail {

namespace {

constexpr const char* kWhere = "F4 interreduction";

}  // namespace

bool InterreductionPlan::fits(const std::vector<ModPolynomial>& minimal) const {
  if (empty() || minimal.size() != support_ends_.size()) return false;
  std::size_t begin = 0;
  for (std::size_t i = 0; i < minimal.size(); ++i) {
    const std::vector<std::int32_t>& m = minimal[i].monomials;
    if (m.size() != support_ends_[i] - begin ||
        !std::equal(m.begin(), m.end(), supports_.begin() + static_cast<long>(begin))) {
      return false;
    }
    begin = support_ends_[i];
  }
  return true;
}

std::vector<ModPolynomial> reduce_basis_by_matrix(const Ring& ring, const ModularArithmetic& arithmetic,
                                                  std::vector<ModPolynomial> basis, const Budget& budget,
                                                  const InterreductionPlan* replay, InterreductionPlan* record) {
  const std::vector<ModPolynomial> minimal = arithmetic.minimal_basis(std::move(basis));
  InterreductionPlan made;
  const bool planned = replay != nullptr && replay->fits(minimal);
  if (!planned) {
    // Symbolic preprocessing: the elements, then a multiple u·g for every monomial of
    // a tail that a leading monomial divides.
    const std::size_t w = ring.monomial_size();
    std::vector<BasicReducer<ModPolynomial>> reducers;
    for (const auto& g : minimal) reducers.push_back({&g, ring.divisor_mask(g.monomials.data()), 0});
    RowCollector<ModPolynomial> collector(ring, minimal, budget, kWhere);
    const std::vector<std::int32_t> one(w, 0);
    for (std::size_t i = 0; i < minimal.size(); ++i) made.element_rows_.push_back(collector.add(i, one.data()));
    collector.add_reducers(reducers);
    MatrixColumns columns = number_columns(ring, collector.table());
    const std::vector<std::int64_t> shortest = shortest_rows_by_lead(collector.rows(), collector.table().size());
    made.rows_.reserve(collector.rows().size());
    for (const PendingRow& pending : collector.rows()) made.rows_.push_back(numbered_row(pending, columns.of_id));
    made.pivot_.assign(columns.of_id.size(), -1);
    for (std::size_t id = 0; id < shortest.size(); ++id) made.pivot_[columns.of_id[id]] = shortest[id];
    made.column_monomials_ = std::move(columns.monomials);
    if (record != nullptr) {
      for (const auto& g : minimal) {
        made.supports_.insert(made.supports_.end(), g.monomials.begin(), g.monomials.end());
        made.support_ends_.push_back(made.supports_.size());
      }
    }
  }
  const InterreductionPlan& plan = planned ? *replay : made;

  // The rows with this prime's coefficients, and each element's tail eliminated.
  std::vector<MatrixRow> rows(plan.rows_.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    rows[r].columns = plan.rows_[r].columns;
    rows[r].coefficients = minimal[plan.rows_[r].poly].coefficients.data();
  }
  std::vector<const MatrixRow*> pivot(plan.pivot_.size(), nullptr);
  for (std::size_t c = 0; c < pivot.size(); ++c) {
    if (plan.pivot_[c] >= 0) pivot[c] = &rows[static_cast<std::size_t>(plan.pivot_[c])];
  }
  const std::size_t w = ring.monomial_size();
  std::vector<std::uint64_t> acc(pivot.size(), 0);
  std::vector<ModPolynomial> reduced;
  reduced.reserve(minimal.size());
  for (std::size_t i = 0; i < minimal.size(); ++i) {
    budget.check(kWhere);
    const MatrixRow out = reduce_tail(rows[plan.element_rows_[i]], pivot, acc, arithmetic.modulus());
    budget.charge_work(kWorkPerStep + kWorkPerModularTerm * out.size(), kWhere);
    budget.check_terms(out.size(), kWhere);
    reduced.push_back(row_polynomial(out, plan.column_monomials_, w));
  }
  if (record != nullptr && !planned) *record = std::move(made);
  return reduced;
}

}  // namespace implicitizer::detail
