#include "macaulay_rows.hpp"

#include <algorithm>
#include <numeric>

namespace implicitizer::detail {

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

MatrixColumns number_columns(const Ring& ring, const MonomialTable& table) {
  std::vector<std::uint32_t> order(table.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return ring.compare(table.monomial(a), table.monomial(b)) > 0; });
  const std::size_t w = ring.monomial_size();
  MatrixColumns columns;
  columns.of_id.resize(table.size());
  columns.monomials.resize(table.size() * w);
  for (std::size_t c = 0; c < order.size(); ++c) {
    columns.of_id[order[c]] = static_cast<std::uint32_t>(c);
    std::copy(table.monomial(order[c]), table.monomial(order[c]) + w, columns.monomials.data() + c * w);
  }
  return columns;
}

std::vector<std::int64_t> shortest_rows_by_lead(const std::vector<PendingRow>& rows, std::size_t ids) {
  std::vector<std::int64_t> shortest(ids, -1);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::int64_t& s = shortest[rows[r].ids.front()];
    if (s < 0 || rows[static_cast<std::size_t>(s)].ids.size() > rows[r].ids.size()) s = static_cast<std::int64_t>(r);
  }
  return shortest;
}

}  // namespace implicitizer::detail
