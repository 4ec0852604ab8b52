#include "json_writer.hpp"

#include <cmath>

#include "implicitizer/modular/one_per_thread.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer::json {

namespace {

// Printing this many terms is worth a second thread (a thread costs well under a
// millisecond; these terms take several).
constexpr std::size_t kTermsWorthAThread = 5'000;

}  // namespace

Writer& configure(Writer& w) {
  w.SetMaxDecimalPlaces(3);
  return w;
}

void write_string(Writer& w, std::string_view s) { w.String(s.data(), static_cast<rapidjson::SizeType>(s.size())); }

void write_strings(Writer& w, const std::vector<std::string>& strings) {
  w.StartArray();
  for (const std::string& s : strings) write_string(w, s);
  w.EndArray();
}

void write_milliseconds(Writer& w, double ms) { w.Double(std::isfinite(ms) && ms > 0 ? ms : 0.0); }

void write_polynomials(Writer& w, const std::vector<Polynomial>& polynomials) {
  // Printing a coefficient takes a gcd with the content's denominator (printer.cpp),
  // and a reduced basis can run to tens of thousands of terms: a large answer is
  // printed on two threads, every other polynomial each (docs/benchmarks.md, "Where it
  // stands: followers, the candidate in integers, the basis printed on two threads").
  std::size_t terms = 0;
  for (const Polynomial& p : polynomials) terms += p.num_terms();
  const std::size_t threads = terms >= kTermsWorthAThread ? 2 : 1;
  std::vector<std::string> printed(polynomials.size());
  run_one_per_thread(threads, [&](std::size_t t) {
    for (std::size_t i = t; i < polynomials.size(); i += threads) printed[i] = to_string(polynomials[i]);
  });
  w.StartArray();
  for (const std::string& s : printed) write_string(w, s);
  w.EndArray();
}

void write_buchberger_stats_members(Writer& w, const BuchbergerStats& s) {
  w.Key("pairs");
  w.Uint64(s.pairs_created);
  w.Key("product_criterion");
  w.Uint64(s.product_criterion);
  w.Key("chain_criterion");
  w.Uint64(s.chain_criterion);
  w.Key("reductions");
  w.Uint64(s.reductions);
  w.Key("zero_reductions");
  w.Uint64(s.zero_reductions);
  w.Key("reduction_steps");
  w.Uint64(s.reduction_steps);
  w.Key("work");
  w.Uint64(s.work);
  w.Key("max_degree");
  w.Int(s.max_degree);
  w.Key("basis_size");
  w.Uint64(s.basis_size);
  w.Key("groebner_ms");
  write_milliseconds(w, s.elapsed_ms);
}

void write_modular_stats(Writer& w, const ModularGroebnerStats& s) {
  w.StartObject();
  w.Key("primes");
  w.Uint64(s.primes);
  w.Key("lifted_primes");
  w.Uint64(s.lifted_primes);
  w.Key("unlucky_primes");
  w.Uint64(s.unlucky_primes);
  w.Key("bad_primes");
  w.Uint64(s.bad_primes);
  w.Key("replayed_primes");
  w.Uint64(s.replayed_primes);
  w.Key("replay_failures");
  w.Uint64(s.replay_failures);
  w.Key("trace_dropped");
  w.Bool(s.trace_dropped);
  w.Key("reconstructions");
  w.Uint64(s.reconstructions);
  w.Key("checking_primes");
  w.Uint64(s.checking_primes);
  // As decimal strings: the primes pass 2^53, past which a JavaScript client's
  // numbers round.
  w.Key("random_primes");
  w.StartArray();
  for (const std::uint64_t p : s.random_primes) write_string(w, std::to_string(p));
  w.EndArray();
  w.Key("rejected_candidates");
  w.Uint64(s.rejected_candidates);
  w.Key("homogenized");
  w.Bool(s.homogenized);
  w.Key("proven");
  w.Bool(s.proven);
  w.Key("verification_pairs");
  w.Uint64(s.verification_pairs);
  w.Key("proof_content_divisions");
  w.Uint64(s.proof_content_divisions);
  w.Key("threads");
  w.Uint64(s.threads);
  w.Key("modular_ms");
  write_milliseconds(w, s.modular_ms);
  w.Key("lift_ms");
  write_milliseconds(w, s.lift_ms);
  w.Key("verify_ms");
  write_milliseconds(w, s.verify_ms);
  w.Key("dehomogenize_ms");
  write_milliseconds(w, s.dehomogenize_ms);
  w.EndObject();
}

std::string finish(const rapidjson::StringBuffer& buffer) { return std::string(buffer.GetString(), buffer.GetSize()); }

}  // namespace implicitizer::json
