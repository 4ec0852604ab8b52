#pragma once
// Private to the groebner module: the rows of a Macaulay matrix before they have
// coefficients, for any coefficient domain. F4's matrices modulo a prime
// (f4_matrix.hpp) and the proof's matrices over ℤ (rational_proof.hpp) are built
// the same way: monomial multiples u·g of basis elements, every monomial met that a
// leading monomial divides given one reducer row (symbolic preprocessing, Faugère
// 1999 §2.3), the columns the monomials in decreasing order.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "reducer.hpp"

namespace implicitizer::detail {

// The monomials met while building one matrix, each with a dense id, found by an
// open-addressing hash on their exponents (mathicgb and msolve keep one such table
// per matrix: hashing beats a tree of monomials by the comparisons a tree needs).
class MonomialTable {
 public:
  explicit MonomialTable(const Ring& ring);

  // The id of `m` (monomial_size words), adding it if new.
  std::uint32_t insert(const std::int32_t* m);
  // The monomial with id `id`.
  const std::int32_t* monomial(std::uint32_t id) const { return words_.data() + std::size_t{id} * width_; }
  std::size_t size() const { return hashes_.size(); }

 private:
  std::uint64_t hash(const std::int32_t* m) const;
  void grow();

  const Ring& ring_;
  std::size_t width_;
  std::vector<std::int32_t> words_;    // width_ words per id
  std::vector<std::uint64_t> hashes_;  // per id
  std::vector<std::uint32_t> slots_;   // id + 1, 0 when empty; size a power of two
};

// A matrix's columns: the table's monomials in decreasing order, left to right.
struct MatrixColumns {
  std::vector<std::uint32_t> of_id;     // the column of each table id
  std::vector<std::int32_t> monomials;  // monomial_size words per column
};

// Numbers the columns of the monomials in `table`.
MatrixColumns number_columns(const Ring& ring, const MonomialTable& table);

// A row before the columns are numbered: basis element `poly` times a monomial, as
// the table ids of its terms (the leading one first).
struct PendingRow {
  std::size_t poly = 0;
  std::vector<std::uint32_t> ids;
};

// Per table id (of `ids`), the index in `rows` of the shortest row leading there, or
// −1 where no row does: the pivot of that column, the cheapest to subtract.
std::vector<std::int64_t> shortest_rows_by_lead(const std::vector<PendingRow>& rows, std::size_t ids);

// Collects the rows of one matrix over `basis` (polynomials with `monomials` and
// size(), terms decreasing): each multiple u·g at most once, and which monomials
// already lead a row. `where` names the phase in budget stops.
template <class Poly>
class RowCollector {
 public:
  RowCollector(const Ring& ring, const std::vector<Poly>& basis, const Budget& budget, const char* where)
      : ring_(ring), basis_(basis), budget_(budget), where_(where), table_(ring), scratch_(ring.monomial_size()) {}

  MonomialTable& table() { return table_; }
  std::vector<PendingRow>& rows() { return rows_; }
  bool leads_a_row(std::uint32_t id) const { return id < has_lead_.size() && has_lead_[id] != 0; }

  // Adds shift·basis[poly] unless that row is already there; its index in rows().
  std::size_t add(std::size_t poly, const std::int32_t* shift) {
    const Poly& g = basis_[poly];
    const std::size_t w = ring_.monomial_size();
    ring_.multiply(g.monomials.data(), shift, scratch_.data());
    const std::uint32_t lead = table_.insert(scratch_.data());
    const auto [made, added] = made_.try_emplace((std::uint64_t{poly} << 32) | lead, rows_.size());
    if (!added) return made->second;
    if ((rows_.size() & 63) == 0) budget_.check(where_);
    budget_.check_terms(g.size(), where_);
    PendingRow row;
    row.poly = poly;
    row.ids.reserve(g.size());
    row.ids.push_back(lead);
    for (std::size_t i = 1; i < g.size(); ++i) {
      ring_.multiply(g.monomials.data() + i * w, shift, scratch_.data());
      row.ids.push_back(table_.insert(scratch_.data()));
    }
    if (has_lead_.size() <= lead) has_lead_.resize(std::max<std::size_t>(lead + 1, 2 * has_lead_.size()), 0);
    has_lead_[lead] = 1;
    rows_.push_back(std::move(row));
    return rows_.size() - 1;
  }

  // Symbolic preprocessing: every monomial met (the table grows as rows are added)
  // that no row leads yet and some leading monomial of `reducers` divides gets its
  // reducer row (find_reducer's choice).
  void add_reducers(const std::vector<BasicReducer<Poly>>& reducers) {
    const std::size_t w = ring_.monomial_size();
    std::vector<std::int32_t> m(w), shift(w);
    for (std::uint32_t id = 0; id < table_.size(); ++id) {
      if (leads_a_row(id)) continue;
      const std::int32_t* monomial = table_.monomial(id);
      std::copy(monomial, monomial + w, m.data());  // the table may reallocate below
      const BasicReducer<Poly>* r = find_reducer(ring_, m.data(), reducers);
      if (r == nullptr) continue;
      ring_.divide(m.data(), r->polynomial->monomials.data(), shift.data());
      add(static_cast<std::size_t>(r->polynomial - basis_.data()), shift.data());
    }
  }

 private:
  const Ring& ring_;
  const std::vector<Poly>& basis_;
  const Budget& budget_;
  const char* where_;
  MonomialTable table_;
  std::vector<PendingRow> rows_;
  std::unordered_map<std::uint64_t, std::size_t> made_;  // (poly, lead id) → row
  std::vector<char> has_lead_;                           // by monomial id
  std::vector<std::int32_t> scratch_;
};

}  // namespace implicitizer::detail
