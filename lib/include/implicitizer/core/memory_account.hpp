#pragma once
/// \file
/// The bytes one computation holds, counted where they are allocated.
///
/// A process-wide allocation hook (operator new and delete, GMP's and FLINT's
/// allocators, all installed by memory_account.cpp) charges every block to the account
/// of the thread that allocates or frees it; a MemoryScope attaches a thread to an
/// account while it computes for it. Blocks are measured with malloc_usable_size, so a
/// block freed on any thread attached to the same account is credited exactly. A block
/// allocated under one account and freed under none (an answer handed to a network
/// thread) stays charged to it, which is harmless: the account ends with its
/// computation. Threads attached to no account pay one thread-local read per call.
///
/// Enforcement has two halves, because C code (GMP, FLINT) cannot take an exception
/// from its allocator: every allocation past the limit marks the account exceeded, and
/// Budget::check() then stops the computation at its next check with Limit::memory;
/// a single C++ allocation of kLargeAllocationBytes or more that would pass the limit
/// is refused at once with std::bad_alloc, so that one huge vector cannot take the
/// machine before the next check. Sanitizer builds (the fuzzers) keep their own
/// allocator and count nothing.

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace implicitizer {

/// A C++ allocation at least this large that would pass an account's limit throws
/// std::bad_alloc instead of being made.
inline constexpr std::size_t kLargeAllocationBytes = std::size_t{1} << 20;

/// The memory of one computation: bytes held now, the peak, and a limit.
class MemoryAccount {
 public:
  /// An account that is exceeded once it holds more than `limit_bytes` (0 = no limit,
  /// counting only).
  explicit MemoryAccount(std::size_t limit_bytes = 0) : limit_(limit_bytes) {}
  MemoryAccount(const MemoryAccount&) = delete;
  MemoryAccount& operator=(const MemoryAccount&) = delete;

  /// The limit in bytes (0 = none).
  std::size_t limit_bytes() const { return limit_; }
  /// Bytes held now by blocks charged to this account (never negative).
  std::size_t bytes() const;
  /// The largest value bytes() has had.
  std::size_t peak_bytes() const { return peak_.load(std::memory_order_relaxed); }
  /// Whether the account ever held more than its limit (sticky).
  bool exceeded() const { return exceeded_.load(std::memory_order_relaxed); }
  /// Whether charging `more` bytes now would pass the limit.
  bool would_exceed(std::size_t more) const;

  /// Charges a block of `n` bytes (called by the allocation hooks).
  void allocated(std::size_t n) noexcept;
  /// Credits a block of `n` bytes (called by the allocation hooks).
  void freed(std::size_t n) noexcept;

 private:
  const std::size_t limit_;
  // Signed: a computation may free blocks that were allocated before it attached.
  std::atomic<std::int64_t> bytes_{0};
  std::atomic<std::size_t> peak_{0};
  std::atomic<bool> exceeded_{false};
};

/// The account the calling thread is attached to, or null.
MemoryAccount* current_memory_account() noexcept;

/// Whether this build counts allocations (false in sanitizer builds, whose runtime
/// owns the allocator).
bool memory_accounting_enabled() noexcept;

/// Attaches the calling thread to `account` (null detaches it) until destroyed, then
/// restores the previous attachment. Threads a computation starts attach to the
/// account of the thread that started them (run_one_per_thread does).
class MemoryScope {
 public:
  explicit MemoryScope(MemoryAccount* account) noexcept;
  ~MemoryScope();
  MemoryScope(const MemoryScope&) = delete;
  MemoryScope& operator=(const MemoryScope&) = delete;

 private:
  MemoryAccount* previous_;
};

/// Gives freed memory back to the system (glibc's malloc_trim): after a computation
/// whose peak passed `threshold_bytes`, so that one large request does not leave the
/// process holding gigabytes it no longer uses. Returns whether it trimmed.
bool release_free_memory(std::size_t peak_bytes, std::size_t threshold_bytes);

}  // namespace implicitizer
