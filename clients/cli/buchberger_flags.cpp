#include "buchberger_flags.hpp"

namespace implicitizer::cli {

BuchbergerVariant buchberger_variant_from(const Arguments& arguments) {
  BuchbergerVariant variant;
  if (const auto strategy = arguments.value("strategy")) {
    if (*strategy == "auto") {
      variant.strategy = SelectionStrategy::automatic;
    } else if (*strategy == "normal") {
      variant.strategy = SelectionStrategy::normal;
    } else if (*strategy == "sugar") {
      variant.strategy = SelectionStrategy::sugar;
    } else {
      throw UsageError("--strategy must be auto, normal or sugar, not '" + *strategy + "'");
    }
  }
  if (const auto criteria = arguments.value("criteria")) {
    if (*criteria == "gm") {
      variant.product_criterion = true;
      variant.chain_criterion = ChainCriterion::gebauer_moller;
    } else if (*criteria == "seed") {
      variant.product_criterion = true;
      variant.chain_criterion = ChainCriterion::buchberger;
    } else if (*criteria == "product") {
      variant.product_criterion = true;
      variant.chain_criterion = ChainCriterion::off;
    } else if (*criteria == "none") {
      variant.product_criterion = false;
      variant.chain_criterion = ChainCriterion::off;
    } else {
      throw UsageError("--criteria must be gm, seed, product or none, not '" + *criteria + "'");
    }
  }
  return variant;
}

Budget budget_from(const Arguments& arguments) {
  Budget budget;
  if (const auto terms = arguments.value("max-terms")) budget.set_max_terms(parse_count(*terms, "max-terms"));
  if (const auto memory = arguments.value("max-memory")) {
    budget.set_max_memory(parse_memory_size(*memory, "max-memory"));
  }
  return budget;
}

std::optional<double> timeout_from(const Arguments& arguments) {
  if (const auto timeout = arguments.value("timeout")) return parse_seconds(*timeout, "timeout");
  return std::nullopt;
}

}  // namespace implicitizer::cli
