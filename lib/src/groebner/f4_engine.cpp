#include "f4_engine.hpp"

#include <algorithm>
#include <optional>

#include "f4_matrix.hpp"
#include "f4_row_echelon.hpp"
#include "f4_trace.hpp"
#include "growing_basis.hpp"
#include "s_pair_queue.hpp"

namespace implicitizer::detail {

namespace {

class F4Engine {
 public:
  F4Engine(const Ring& ring, const ModularArithmetic& arithmetic, const BuchbergerParams& params,
           BuchbergerStats& stats, F4Trace* learn, std::size_t threads)
      : ring_(ring),
        arithmetic_(arithmetic),
        params_(params),
        stats_(stats),
        learn_(learn),
        threads_(threads),
        queue_(ring, params, stats),
        use_sugar_(params.variant.strategy == SelectionStrategy::sugar ||
                   (params.variant.strategy == SelectionStrategy::automatic && ring.is_elimination_order())) {}

  F4Outcome run(std::vector<ModPolynomial> generators) {
    F4Outcome out;
    if (learn_ != nullptr) {
      learn_->start(static_cast<std::size_t>(
          std::count_if(generators.begin(), generators.end(), [](const ModPolynomial& g) { return !g.empty(); })));
    }
    if (!basis_.insert_generators(std::move(generators), params_.budget, "F4 (the generators)")) {
      out.unit = true;
      return out;
    }
    std::vector<SPair> selected;
    while (select(selected)) {
      if (reduce_selected(selected)) {
        out.unit = true;
        return out;
      }
    }
    if (learn_ != nullptr) {
      std::vector<std::size_t> minimal;
      for (std::size_t i = 0; i < basis_.entries().size(); ++i) {
        if (!basis_.entries()[i].redundant) minimal.push_back(i);
      }
      learn_->finish(std::move(minimal));
    }
    out.basis = basis_.take_nonredundant();
    return out;
  }

 private:
  std::int32_t key(const SPair& p) const { return use_sugar_ ? p.sugar : p.lcm_degree; }

  // The next pairs: all those of the smallest degree (sugar) the queue yields in a
  // row. The queue orders by sugar, or by lcm (degree first on graded orders); on
  // other orders a degree may come in several runs, which is still correct (any
  // subset of the pairs may be selected), only less batched. The first pair of the
  // next degree waits in held_.
  bool select(std::vector<SPair>& selected) {
    selected.clear();
    SPair p;
    if (held_) {
      selected.push_back(std::move(*held_));
      held_.reset();
    } else if (queue_.pop(basis_.entries(), p)) {
      selected.push_back(std::move(p));
    } else {
      return false;
    }
    while (queue_.pop(basis_.entries(), p)) {
      if (key(p) != key(selected.front())) {
        held_ = std::move(p);
        break;
      }
      selected.push_back(std::move(p));
    }
    return true;
  }

  // One F4 step on the selected pairs; true when it found the unit ideal.
  bool reduce_selected(const std::vector<SPair>& selected) {
    params_.budget.check("F4");
    // Pairs selected so far of those known: the total grows as new elements form pairs.
    params_.budget.report_step("F4 (S-pairs)", stats_.reductions, stats_.reductions + queue_.pairs_left());
    std::vector<SelectedPair> pairs;
    std::int32_t sugar = 0;
    for (const SPair& p : selected) {
      pairs.push_back({p.i, p.j});
      sugar = std::max(sugar, p.sugar);
      stats_.max_degree = std::max(stats_.max_degree, p.lcm_degree);
    }
    const MacaulayMatrix matrix =
        build_macaulay_matrix(ring_, basis_.polynomials(), basis_.reducers(), pairs, params_.budget);
    EchelonResult echelon = reduce_to_row_echelon(matrix, arithmetic_.modulus(), params_.budget, threads_);
    stats_.reductions += selected.size();
    stats_.reduction_steps += matrix.to_reduce.size();
    stats_.work += echelon.work;
    stats_.zero_reductions += selected.size() - std::min(selected.size(), echelon.new_rows.size());
    if (learn_ != nullptr) learn_->record_step(ring_, matrix, echelon);
    // Decreasing leading monomials (increasing columns): an element whose leading
    // monomial a later one divides is then marked redundant by the later one's update.
    std::sort(echelon.new_rows.begin(), echelon.new_rows.end(),
              [](const MatrixRow& a, const MatrixRow& b) { return a.lead() < b.lead(); });
    const std::size_t w = ring_.monomial_size();
    for (const MatrixRow& row : echelon.new_rows) {
      ModPolynomial g = row_polynomial(row, matrix.column_monomials, w);
      if (basis_.is_constant(g)) return true;
      basis_.insert(std::move(g), sugar);
    }
    return false;
  }

  const Ring& ring_;
  const ModularArithmetic& arithmetic_;
  const BuchbergerParams& params_;
  BuchbergerStats& stats_;
  F4Trace* learn_;
  std::size_t threads_;  // for the matrices' echelon step
  SPairQueue queue_;
  bool use_sugar_;
  std::optional<SPair> held_;
  GrowingBasis<ModPolynomial> basis_{ring_, queue_};
};

}  // namespace

F4Outcome run_f4(const Ring& ring, const ModularArithmetic& arithmetic, std::vector<ModPolynomial> generators,
                 const BuchbergerParams& params, BuchbergerStats& stats, F4Trace* learn, std::size_t threads) {
  return F4Engine(ring, arithmetic, params, stats, learn, threads).run(std::move(generators));
}

}  // namespace implicitizer::detail
