#pragma once
/// \file
/// The batch loop every multi-modular computation here shares: independent jobs
/// (one per prime), one per thread, the first on the calling thread, and the first
/// error rethrown once all have ended. Callers combine the results in job order,
/// so that answers do not depend on scheduling.

#include <flint/flint.h>

#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

#include "implicitizer/core/memory_account.hpp"

namespace implicitizer {

/// Runs work(0), …, work(count − 1) concurrently, work(0) on the calling thread;
/// returns when all have ended, rethrowing the exception of the lowest-numbered job
/// that threw. Every thread charges its memory to the calling thread's account.
template <typename Work>
void run_one_per_thread(std::size_t count, const Work& work) {
  std::vector<std::exception_ptr> errors(count);
  MemoryAccount* const account = current_memory_account();
  auto guarded = [&](std::size_t i) {
    const MemoryScope scope(account);
    try {
      work(i);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t i = 1; i < count; ++i) {
    pool.emplace_back([&guarded, i] {
      guarded(i);
      // FLINT keeps per-thread caches (fmpz's freed integers among them) that only
      // flint_cleanup() in the same thread frees: without it every worker that did
      // fmpz arithmetic leaves them behind when it ends (the request fuzzer's leak
      // report).
      flint_cleanup();
    });
  }
  if (count > 0) guarded(0);
  for (auto& t : pool) t.join();
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace implicitizer
