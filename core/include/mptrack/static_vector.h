// StaticVector<T, N>: a fixed-capacity vector stored inside the object.
//
// std::array<T, N> plus a size. T must own no resources: trivially
// destructible, default constructible and copy-assignable. Our
// measurements and reports are PODs or hold fixed-size Eigen matrices (which
// are not trivially copyable only because Eigen declares its copy
// constructor); none of them allocates, so no placement-new or
// aligned_storage is needed (compare ETL's vector).
// push_back always checks capacity and reports overflow as a Status, in
// release builds too: unlike gtrack we never clamp silently.
#pragma once

#include <array>
#include <cstddef>
#include <new>
#include <type_traits>

#include "mptrack/status.h"

namespace mptrack {

template <class T, std::size_t N>
class StaticVector {
  static_assert(N > 0, "a zero-capacity StaticVector is not useful");
  static_assert(std::is_trivially_destructible<T>::value,
                "StaticVector holds types that own no resources (trivially destructible)");
  static_assert(std::is_default_constructible<T>::value &&
                    std::is_copy_assignable<T>::value,
                "StaticVector needs default construction and copy assignment");

 public:
  using value_type = T;
  using size_type = std::size_t;
  using iterator = T*;
  using const_iterator = const T*;

  static constexpr std::size_t kCapacity = N;

  constexpr std::size_t size() const { return size_; }
  static constexpr std::size_t capacity() { return N; }
  constexpr bool empty() const { return size_ == 0; }
  constexpr bool full() const { return size_ == N; }

  /// Appends a copy of v. kCapacityExceeded (and nothing stored) when full.
  Status push_back(const T& v) {
    if (size_ == N) return Status::kCapacityExceeded;
    items_[size_++] = v;
    return Status::kOk;
  }

  /// Removes the last element; kBufferEmpty if there is none.
  Status pop_back() {
    if (size_ == 0) return Status::kBufferEmpty;
    --size_;
    return Status::kOk;
  }

  /// Removes element i keeping the order of the others (deterministic
  /// iteration order matters for bit-exactness). kInvalidArgument if i >= size.
  Status erase(std::size_t i) {
    if (i >= size_) return Status::kInvalidArgument;
    for (std::size_t k = i + 1; k < size_; ++k) items_[k - 1] = items_[k];
    --size_;
    return Status::kOk;
  }

  /// Sets the size; new elements are value-initialised. kCapacityExceeded if n > N.
  Status resize(std::size_t n) {
    if (n > N) return Status::kCapacityExceeded;
    // Value-initialise in place (placement new): `items_[k] = T{}` would build a
    // temporary on the stack, kilobytes for a ScanEstimate on a Cortex-M stack.
    for (std::size_t k = size_; k < n; ++k) ::new (static_cast<void*>(&items_[k])) T();  // placement
    size_ = n;
    return Status::kOk;
  }

  void clear() { size_ = 0; }

  // Unchecked element access, like std::vector (callers iterate below size()).
  T& operator[](std::size_t i) { return items_[i]; }
  const T& operator[](std::size_t i) const { return items_[i]; }
  T& back() { return items_[size_ - 1]; }
  const T& back() const { return items_[size_ - 1]; }

  T* data() { return items_.data(); }
  const T* data() const { return items_.data(); }
  iterator begin() { return items_.data(); }
  iterator end() { return items_.data() + size_; }
  const_iterator begin() const { return items_.data(); }
  const_iterator end() const { return items_.data() + size_; }

 private:
  std::array<T, N> items_{};
  std::size_t size_ = 0;
};

}  // namespace mptrack
