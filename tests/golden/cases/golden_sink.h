// The heap-free half of a golden test: what a golden case records into.
//
// A golden case (tests/golden/cases/<name>.cpp) runs a tracker or a front
// end stage on deterministic inputs and adds every value it pins to a
// GoldenSink, as "label f32 <hex>" lines. The same case function is called by
//   - the doctest golden test on Linux targets (x86-64, and under qemu-user
//     aarch64, armhf and big-endian ppc), through test::GoldenFile, which
//     compares with tests/golden/data/<name>.golden read from disk;
//   - the bare-metal runners (tests/baremetal/golden_runner.cpp: Cortex-M7
//     under qemu-system-arm), which compare with the same file embedded in
//     the image.
// So a case may use neither the heap nor exceptions nor iostreams: labels
// are built in a fixed buffer (Label) and large objects live in static
// storage (Slot). Bit patterns are read as integers (memcpy into uint32_t /
// uint64_t), never byte by byte, so the hex text is the same on little- and
// big-endian targets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>

namespace mptrack::test {

/// A label of at most kCapacity - 1 characters, built without the heap:
/// Label("s") + 3 + ".x" gives "s3.x". Overflow truncates and is remembered,
/// so an overlong label can never compare equal by accident.
class Label {
 public:
  static constexpr std::size_t kCapacity = 160;

  Label() { text_[0] = '\0'; }
  Label(const char* s) { append(s); }  // NOLINT: implicit from a literal by design

  Label operator+(const char* s) const {
    Label r = *this;
    r.append(s);
    return r;
  }
  template <class I, std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, bool>, int> = 0>
  Label operator+(I v) const {
    Label r = *this;
    r.append_int(static_cast<std::int64_t>(v));
    return r;
  }
  /// Appends a float's / double's bit pattern as lower-case hex (8 / 16 digits).
  Label bits(float v) const;
  Label bits(double v) const;

  const char* c_str() const { return text_; }
  bool truncated() const { return truncated_; }

  void append(const char* s);
  void append_int(std::int64_t v);
  void append_hex(std::uint64_t v, int digits);

 private:
  char text_[kCapacity];
  std::size_t size_ = 0;
  bool truncated_ = false;
};

/// Where a golden case records its values (see the file comment).
class GoldenSink {
 public:
  void add(const Label& label, float v) { add_f32(label.c_str(), v); }
  void add(const Label& label, double v) { add_f64(label.c_str(), v); }
  template <class I, std::enable_if_t<std::is_integral_v<I>, int> = 0>
  void add(const Label& label, I v) {
    add_i64(label.c_str(), static_cast<std::int64_t>(v));
  }

  /// A precondition of the case (an init or a push that must succeed).
  /// A failed one is counted and reported; the case goes on recording so
  /// the comparison shows where the values part.
  void require(bool ok, const char* what) {
    if (!ok) {
      ++failures_;
      on_failure(what);
    }
  }
  std::size_t failures() const { return failures_; }

 protected:
  GoldenSink() = default;
  GoldenSink(const GoldenSink&) = default;
  GoldenSink& operator=(const GoldenSink&) = default;
  ~GoldenSink() = default;  // not virtual: a virtual one would pull operator delete into bare-metal images

  virtual void add_f32(const char* label, float v) = 0;
  virtual void add_f64(const char* label, double v) = 0;
  virtual void add_i64(const char* label, std::int64_t v) = 0;
  virtual void on_failure(const char* what) = 0;

 private:
  std::size_t failures_ = 0;
};

/// Static storage for one large object of a case (trackers and radar cubes
/// are hundreds of KiB: too big for a thread stack, and no heap on target).
/// Declared at namespace scope it is zero-initialised .bss with no
/// constructor or destructor to register; make() constructs a fresh T in it.
/// T must be trivially destructible in practice (every core type is: fixed
/// Eigen matrices and static_vectors of them); the previous object is
/// destroyed before the next is built anyway.
template <class T>
class Slot {
 public:
  T& make() {
    if (object_ != nullptr) object_->~T();
    object_ = ::new (static_cast<void*>(storage_)) T();
    return *object_;
  }

 private:
  alignas(T) unsigned char storage_[sizeof(T)];
  T* object_;  // zero-initialised at namespace scope: nothing built yet
};

/// Bit patterns as unsigned integers (value, not memory layout).
inline std::uint32_t bits_of(float v) {
  std::uint32_t u = 0;
  std::memcpy(&u, &v, sizeof u);
  return u;
}
inline std::uint64_t bits_of(double v) {
  std::uint64_t u = 0;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

/// Formats one golden line, "label f32 3f800000" / "label f64 ..." /
/// "label i64 -1", into out (capacity cap); returns its length. The one
/// formatter of the line syntax, shared by GoldenFile and the runners.
std::size_t format_line(char* out, std::size_t cap, const char* label, char kind, std::uint64_t bits);

}  // namespace mptrack::test
