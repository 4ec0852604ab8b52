#include "buchberger_flags.hpp"

namespace implicitizer::cli {

BuchbergerParams buchberger_params_from(const Arguments& arguments) {
  BuchbergerParams params;
  if (const auto strategy = arguments.value("strategy")) {
    if (*strategy == "auto") {
      params.variant.strategy = SelectionStrategy::automatic;
    } else if (*strategy == "normal") {
      params.variant.strategy = SelectionStrategy::normal;
    } else if (*strategy == "sugar") {
      params.variant.strategy = SelectionStrategy::sugar;
    } else {
      throw UsageError("--strategy must be auto, normal or sugar, not '" + *strategy + "'");
    }
  }
  if (const auto criteria = arguments.value("criteria")) {
    if (*criteria == "gm") {
      params.variant.product_criterion = true;
      params.variant.chain_criterion = ChainCriterion::gebauer_moller;
    } else if (*criteria == "seed") {
      params.variant.product_criterion = true;
      params.variant.chain_criterion = ChainCriterion::buchberger;
    } else if (*criteria == "product") {
      params.variant.product_criterion = true;
      params.variant.chain_criterion = ChainCriterion::off;
    } else if (*criteria == "none") {
      params.variant.product_criterion = false;
      params.variant.chain_criterion = ChainCriterion::off;
    } else {
      throw UsageError("--criteria must be gm, seed, product or none, not '" + *criteria + "'");
    }
  }
  if (const auto terms = arguments.value("max-terms")) params.budget.set_max_terms(parse_count(*terms, "max-terms"));
  if (const auto memory = arguments.value("max-memory")) {
    params.budget.set_max_memory(parse_memory_size(*memory, "max-memory"));
  }
  return params;
}

std::optional<double> timeout_from(const Arguments& arguments) {
  if (const auto timeout = arguments.value("timeout")) return parse_seconds(*timeout, "timeout");
  return std::nullopt;
}

}  // namespace implicitizer::cli
