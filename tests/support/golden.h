// Golden-vector files: outputs recorded as exact hex bit patterns.
//
// A golden test records every value it wants pinned, then compares the whole
// record with the committed file tests/golden/data/<name>.golden:
//
//   mptrack::test::GoldenFile g("detmath");
//   g.add("dexp_f", y);            // float  -> "dexp_f f32 3f800000"
//   g.add("dexp_d", yd);           // double -> "dexp_d f64 3ff0000000000000"
//   CHECK(g.matches());
//
// GoldenFile is the Linux GoldenSink (tests/golden/cases/golden_sink.h):
// the golden cases record into it in the doctest tests, and into the
// bare-metal runner's sink on the Cortex-M7. The same file is compared on
// x86-64 and, under qemu-user, on aarch64, armhf and big-endian ppc: passing
// everywhere is the proof of cross-target bit-exactness.
//
// Regenerate mode: MPTRACK_GOLDEN_REGENERATE=1 ctest -R golden rewrites the
// files instead of comparing (review the diff, then commit). It refuses to
// run when CI is set, so CI can never bless its own output.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "../golden/cases/golden_sink.h"

namespace mptrack::test {

class GoldenFile final : public GoldenSink {
 public:
  explicit GoldenFile(std::string name);
  GoldenFile(const GoldenFile&) = delete;
  GoldenFile& operator=(const GoldenFile&) = delete;
  ~GoldenFile() = default;

  /// Compares the recorded lines with the committed file (or rewrites it in
  /// regenerate mode). On mismatch prints the first differing lines and a
  /// count to stderr and returns false.
  bool matches() const;

  std::size_t size() const { return lines_.size(); }
  const std::string& path() const { return path_; }

 private:
  void add_f32(const char* label, float v) override;
  void add_f64(const char* label, double v) override;
  void add_i64(const char* label, std::int64_t v) override;
  void add_line(const char* label, char kind, std::uint64_t bits);
  void on_failure(const char* what) override;

  std::string path_;
  std::vector<std::string> lines_;
};

/// Bit pattern of a float/double as lower-case hex (for messages and tests).
std::string hex_bits(float v);
std::string hex_bits(double v);

}  // namespace mptrack::test
