#include "f4_trace.hpp"

#include <algorithm>

namespace implicitizer::detail {

void F4Trace::record_step(const Ring& ring, const MacaulayMatrix& matrix, const EchelonResult& echelon) {
  // The columns the kept rows reach: their own, then, left to right, those of the
  // pivot of every column reached (a pivot's columns lie right of its lead, so one
  // sweep closes the set). The new rows the echelon step made pivots for later rows
  // are combinations of rows and pivots already reached.
  std::vector<char> reached(matrix.columns, 0);
  for (const std::size_t k : echelon.sources) {
    for (const std::uint32_t c : matrix.to_reduce[k].columns) reached[c] = 1;
  }
  std::vector<const MatrixRow*> pivot_at(matrix.columns, nullptr);
  for (const MatrixRow& r : matrix.pivots) pivot_at[r.lead()] = &r;
  std::vector<std::uint32_t> renumbered(matrix.columns, 0);
  auto step = std::make_unique<Step>();
  const std::size_t w = ring.monomial_size();
  for (std::size_t c = 0; c < matrix.columns; ++c) {
    if (reached[c] == 0) continue;
    if (const MatrixRow* r = pivot_at[c]; r != nullptr) {
      for (const std::uint32_t d : r->columns) reached[d] = 1;
    }
    renumbered[c] = static_cast<std::uint32_t>(step->columns++);
    const std::int32_t* m = matrix.column_monomials.data() + c * w;
    step->column_monomials.insert(step->column_monomials.end(), m, m + w);
  }
  auto traced = [&](const MatrixRow& r) {
    Row row{r.poly, {}};
    row.columns.reserve(r.size());
    for (const std::uint32_t c : r.columns) row.columns.push_back(renumbered[c]);
    return row;
  };
  for (const MatrixRow& r : matrix.pivots) {
    if (reached[r.lead()] != 0) step->pivots.push_back(traced(r));
  }
  for (const std::size_t k : echelon.sources) step->to_reduce.push_back(traced(matrix.to_reduce[k]));
  for (const MatrixRow& r : echelon.new_rows) step->new_leads.push_back(renumbered[r.lead()]);
  const Step* published = step.get();
  (steps_.empty() ? first_ : steps_.back()->next).store(published, std::memory_order_release);
  steps_.push_back(std::move(step));
  publications_.fetch_add(1, std::memory_order_release);
  publications_.notify_all();
  if (after_step_) after_step_();
}

void F4Trace::close() {
  after_step_ = nullptr;
  closed_.store(true, std::memory_order_release);
  publications_.fetch_add(1, std::memory_order_release);
  publications_.notify_all();
}

F4Trace::Replay::Replay(std::uint64_t prime, std::vector<ModPolynomial> generators) {
  nmod_init(&modulus_, prime);
  for (auto& g : generators) {
    if (!g.empty()) basis_.push_back(std::move(g));
  }
}

F4Trace::StepResult F4Trace::replay_step(const Ring& ring, Replay& replay, const Budget& budget) const {
  if (replay.left_path_) return StepResult::left_path;
  // Read before the link: a close() seen here came after every step was linked.
  const bool was_closed = closed();
  const Step* step = (replay.last_ == nullptr ? first_ : replay.last_->next).load(std::memory_order_acquire);
  if (step == nullptr) return was_closed ? StepResult::end : StepResult::not_yet;
  // The generators are known once a step is: start() came before it.
  if (replay.steps_ == 0 && replay.basis_.size() != generators_) {
    replay.left_path_ = true;
    return StepResult::left_path;
  }
  budget.check("F4");
  std::vector<ModPolynomial>& basis = replay.basis_;
  MacaulayMatrix matrix;
  matrix.columns = step->columns;
  auto with_coefficients = [&](const Row& r) {
    MatrixRow row;
    row.poly = r.poly;
    row.columns = r.columns;
    row.coefficients = basis[r.poly].coefficients.data();
    return row;
  };
  for (const Row& r : step->pivots) matrix.pivots.push_back(with_coefficients(r));
  for (const Row& r : step->to_reduce) matrix.to_reduce.push_back(with_coefficients(r));
  EchelonResult echelon = reduce_to_row_echelon(matrix, replay.modulus_, budget);
  BuchbergerStats& stats = replay.stats_;
  stats.reductions += matrix.to_reduce.size();
  stats.reduction_steps += matrix.to_reduce.size();
  stats.work += echelon.work;
  replay.last_ = step;
  ++replay.steps_;
  bool same = echelon.new_rows.size() == step->new_leads.size();
  for (std::size_t k = 0; same && k < step->new_leads.size(); ++k)
    same = echelon.new_rows[k].lead() == step->new_leads[k];
  if (!same) {
    replay.left_path_ = true;
    return StepResult::left_path;
  }
  // As the learning run inserted them (f4_engine.cpp): by increasing leading column.
  std::sort(echelon.new_rows.begin(), echelon.new_rows.end(),
            [](const MatrixRow& a, const MatrixRow& b) { return a.lead() < b.lead(); });
  const std::size_t w = ring.monomial_size();
  for (const MatrixRow& row : echelon.new_rows) basis.push_back(row_polynomial(row, step->column_monomials, w));
  return StepResult::replayed;
}

std::optional<F4Outcome> F4Trace::replay(const Ring& ring, Replay& replay, const Budget& budget,
                                         BuchbergerStats& stats) const {
  StepResult result;
  while ((result = replay_step(ring, replay, budget)) == StepResult::replayed) {
  }
  stats.reductions += replay.stats_.reductions;
  stats.reduction_steps += replay.stats_.reduction_steps;
  stats.work += replay.stats_.work;
  if (result != StepResult::end || !complete_ || replay.steps_ != steps_.size()) return std::nullopt;
  if (replay.steps_ == 0 && replay.basis_.size() != generators_) return std::nullopt;
  F4Outcome outcome;
  for (const std::size_t i : minimal_basis_) {
    if (i >= replay.basis_.size()) return std::nullopt;
    outcome.basis.push_back(std::move(replay.basis_[i]));
  }
  return outcome;
}

std::optional<F4Outcome> F4Trace::replay(const Ring& ring, const ModularArithmetic& arithmetic,
                                         std::vector<ModPolynomial> generators, const Budget& budget,
                                         BuchbergerStats& stats) const {
  Replay begun(arithmetic.prime(), std::move(generators));
  return replay(ring, begun, budget, stats);
}

}  // namespace implicitizer::detail
