#include "f4_matrix.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_set>

namespace implicitizer::detail {

namespace {

constexpr const char* kWhere = "F4 symbolic preprocessing";

}  // namespace

MonomialTable::MonomialTable(const Ring& ring) : ring_(ring), width_(ring.monomial_size()), slots_(1024, 0) {}

std::uint64_t MonomialTable::hash(const std::int32_t* m) const {
  // The exponents determine the monomial (the key words are a linear image of them).
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::size_t i = ring_.key_size(); i < width_; ++i) {
    h ^= static_cast<std::uint32_t>(m[i]);
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 32;
  }
  return h;
}

void MonomialTable::grow() {
  std::vector<std::uint32_t> slots(slots_.size() * 2, 0);
  const std::size_t mask = slots.size() - 1;
  for (std::size_t id = 0; id < hashes_.size(); ++id) {
    std::size_t s = hashes_[id] & mask;
    while (slots[s] != 0) s = (s + 1) & mask;
    slots[s] = static_cast<std::uint32_t>(id + 1);
  }
  slots_ = std::move(slots);
}

std::uint32_t MonomialTable::insert(const std::int32_t* m) {
  if (2 * (hashes_.size() + 1) > slots_.size()) grow();
  const std::uint64_t h = hash(m);
  const std::size_t mask = slots_.size() - 1;
  std::size_t s = h & mask;
  while (slots_[s] != 0) {
    const std::uint32_t id = slots_[s] - 1;
    if (hashes_[id] == h && std::equal(m + ring_.key_size(), m + width_, monomial(id) + ring_.key_size())) return id;
    s = (s + 1) & mask;
  }
  const auto id = static_cast<std::uint32_t>(hashes_.size());
  slots_[s] = id + 1;
  hashes_.push_back(h);
  words_.insert(words_.end(), m, m + width_);
  return id;
}

namespace {

// A row before the columns are numbered: basis element `poly` times a monomial, as
// the table ids of its terms.
struct PendingRow {
  std::size_t poly = 0;
  std::vector<std::uint32_t> ids;
};

// Collects the rows of one matrix: each multiple u·g at most once, and which monomials
// already lead a row.
class RowCollector {
 public:
  RowCollector(const Ring& ring, const std::vector<ModPolynomial>& basis, const Budget& budget)
      : ring_(ring), basis_(basis), budget_(budget), table_(ring), scratch_(ring.monomial_size()) {}

  MonomialTable& table() { return table_; }
  std::vector<PendingRow>& rows() { return rows_; }
  bool leads_a_row(std::uint32_t id) const { return id < has_lead_.size() && has_lead_[id] != 0; }

  // Adds shift·basis[poly] unless that row is already there.
  void add(std::size_t poly, const std::int32_t* shift) {
    const ModPolynomial& g = basis_[poly];
    const std::size_t w = ring_.monomial_size();
    ring_.multiply(g.monomials.data(), shift, scratch_.data());
    const std::uint32_t lead = table_.insert(scratch_.data());
    if (!made_.insert((std::uint64_t{poly} << 32) | lead).second) return;
    if ((rows_.size() & 63) == 0) budget_.check(kWhere);
    budget_.check_terms(g.size(), kWhere);
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
  }

 private:
  const Ring& ring_;
  const std::vector<ModPolynomial>& basis_;
  const Budget& budget_;
  MonomialTable table_;
  std::vector<PendingRow> rows_;
  std::unordered_set<std::uint64_t> made_;  // (poly, lead id) of the rows added
  std::vector<char> has_lead_;              // by monomial id
  std::vector<std::int32_t> scratch_;
};

// The columns: the table's monomials in decreasing order; column_of[id].
std::vector<std::uint32_t> number_columns(const Ring& ring, const MonomialTable& table, MacaulayMatrix& matrix) {
  std::vector<std::uint32_t> order(table.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return ring.compare(table.monomial(a), table.monomial(b)) > 0; });
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
    row.coefficients = basis[pending[r].poly].coefficients.data();
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
  RowCollector collector(ring, basis, budget);
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
  // Symbolic preprocessing: every monomial met (the table grows as rows are added)
  // that no row leads yet and some leading monomial divides gets its reducer row.
  std::vector<std::int32_t> m(w);
  for (std::uint32_t id = 0; id < collector.table().size(); ++id) {
    if (collector.leads_a_row(id)) continue;
    const std::int32_t* monomial = collector.table().monomial(id);
    std::copy(monomial, monomial + w, m.data());  // the table may reallocate below
    const BasicReducer<ModPolynomial>* r = find_reducer(ring, m.data(), reducers);
    if (r == nullptr) continue;
    ring.divide(m.data(), r->polynomial->monomials.data(), shift.data());
    collector.add(static_cast<std::size_t>(r->polynomial - basis.data()), shift.data());
  }
  MacaulayMatrix matrix;
  const std::vector<std::uint32_t> column_of = number_columns(ring, collector.table(), matrix);
  split_rows(collector.rows(), column_of, basis, matrix);
  return matrix;
}

}  // namespace implicitizer::detail
