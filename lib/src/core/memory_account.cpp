#include "implicitizer/core/memory_account.hpp"

#include <flint/flint.h>
#include <gmp.h>
#include <malloc.h>

#include <cstdlib>
#include <new>

// Sanitizer runtimes replace malloc and operator new themselves; replacing them again
// here would hide their checks, so those builds count nothing.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define IMPLICITIZER_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define IMPLICITIZER_COUNT_ALLOCATIONS 0
#endif
#endif
#ifndef IMPLICITIZER_COUNT_ALLOCATIONS
#define IMPLICITIZER_COUNT_ALLOCATIONS 1
#endif

namespace implicitizer {

namespace {

// A plain pointer: no constructor or destructor, so the hooks may read it at any
// point of a thread's life, its start and exit included.
thread_local MemoryAccount* t_account = nullptr;

}  // namespace

std::size_t MemoryAccount::bytes() const {
  const std::int64_t b = bytes_.load(std::memory_order_relaxed);
  return b > 0 ? static_cast<std::size_t>(b) : 0;
}

bool MemoryAccount::would_exceed(std::size_t more) const { return limit_ != 0 && bytes() + more > limit_; }

void MemoryAccount::allocated(std::size_t n) noexcept {
  const std::int64_t now =
      bytes_.fetch_add(static_cast<std::int64_t>(n), std::memory_order_relaxed) + static_cast<std::int64_t>(n);
  if (now <= 0) return;
  const auto held = static_cast<std::size_t>(now);
  std::size_t peak = peak_.load(std::memory_order_relaxed);
  while (held > peak && !peak_.compare_exchange_weak(peak, held, std::memory_order_relaxed)) {
  }
  if (limit_ != 0 && held > limit_) exceeded_.store(true, std::memory_order_relaxed);
}

void MemoryAccount::freed(std::size_t n) noexcept {
  bytes_.fetch_sub(static_cast<std::int64_t>(n), std::memory_order_relaxed);
}

MemoryAccount* current_memory_account() noexcept { return t_account; }

bool memory_accounting_enabled() noexcept { return IMPLICITIZER_COUNT_ALLOCATIONS != 0; }

MemoryScope::MemoryScope(MemoryAccount* account) noexcept : previous_(t_account) { t_account = account; }

MemoryScope::~MemoryScope() { t_account = previous_; }

bool release_free_memory(std::size_t peak_bytes, std::size_t threshold_bytes) {
  if (peak_bytes < threshold_bytes) return false;
  malloc_trim(0);
  return true;
}

}  // namespace implicitizer

#if IMPLICITIZER_COUNT_ALLOCATIONS

namespace {

using implicitizer::kLargeAllocationBytes;
using implicitizer::MemoryAccount;
using implicitizer::t_account;

void charge(void* p) noexcept {
  if (p != nullptr && t_account != nullptr) t_account->allocated(malloc_usable_size(p));
}

void credit(void* p) noexcept {
  if (p != nullptr && t_account != nullptr) t_account->freed(malloc_usable_size(p));
}

// ---- C allocators (GMP, FLINT): count, never fail differently from malloc.

void* counted_malloc(std::size_t n) {
  void* p = std::malloc(n);
  charge(p);
  return p;
}

void* counted_calloc(std::size_t count, std::size_t n) {
  void* p = std::calloc(count, n);
  charge(p);
  return p;
}

void* counted_realloc(void* old, std::size_t n) {
  credit(old);
  void* p = std::realloc(old, n);
  // A failed realloc leaves the old block in place.
  charge(p != nullptr ? p : old);
  return p;
}

void counted_free(void* p) {
  credit(p);
  std::free(p);
}

void* gmp_realloc(void* old, std::size_t, std::size_t n) { return counted_realloc(old, n); }
void gmp_free(void* p, std::size_t) { counted_free(p); }

// GMP and FLINT allocate through these from the start of main: static initialization
// of this file (linked wherever a Budget is, which every computation takes). Blocks
// either library allocated before hold plain malloc memory, which these free alike.
[[maybe_unused]] const bool c_allocators_installed = [] {
  mp_set_memory_functions(counted_malloc, gmp_realloc, gmp_free);
  __flint_set_memory_functions(counted_malloc, counted_calloc, counted_realloc, counted_free);
  return true;
}();

// ---- operator new and delete.

void* allocate(std::size_t n, std::size_t alignment, bool nothrow) {
  MemoryAccount* account = t_account;
  if (account != nullptr && n >= kLargeAllocationBytes && account->would_exceed(n)) {
    // Marks the account as a large block would have, so that the computation stops
    // even if something catches the bad_alloc.
    account->allocated(n);
    account->freed(n);
    if (nothrow) return nullptr;
    throw std::bad_alloc();
  }
  if (n == 0) n = 1;
  void* p = nullptr;
  for (;;) {
    if (alignment <= alignof(std::max_align_t)) {
      p = std::malloc(n);
    } else if (posix_memalign(&p, alignment, n) != 0) {
      p = nullptr;
    }
    if (p != nullptr) break;
    std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) {
      if (nothrow) return nullptr;
      throw std::bad_alloc();
    }
    handler();
  }
  charge(p);
  return p;
}

void release(void* p) noexcept {
  credit(p);
  std::free(p);
}

constexpr std::size_t kDefaultAlignment = alignof(std::max_align_t);

}  // namespace

void* operator new(std::size_t n) { return allocate(n, kDefaultAlignment, false); }
void* operator new[](std::size_t n) { return allocate(n, kDefaultAlignment, false); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n, kDefaultAlignment, true);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n, kDefaultAlignment, true);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a), false); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a), false); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  try {
    return allocate(n, static_cast<std::size_t>(a), true);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  try {
    return allocate(n, static_cast<std::size_t>(a), true);
  } catch (...) {
    return nullptr;
  }
}

void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }

#endif  // IMPLICITIZER_COUNT_ALLOCATIONS
