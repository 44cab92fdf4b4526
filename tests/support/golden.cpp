#include "golden.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#ifndef MPTRACK_GOLDEN_DIR
#error "MPTRACK_GOLDEN_DIR must point at tests/golden/data"
#endif

namespace mptrack::test {

namespace {
bool env_set(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && v[0] != '\0' && std::strcmp(v, "0") != 0 && std::strcmp(v, "false") != 0;
}
}  // namespace

std::string hex_bits(float v) {
  std::uint32_t u = 0;
  std::memcpy(&u, &v, sizeof u);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08" PRIx32, u);
  return buf;
}

std::string hex_bits(double v) {
  std::uint64_t u = 0;
  std::memcpy(&u, &v, sizeof u);
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, u);
  return buf;
}

GoldenFile::GoldenFile(std::string name)
    : path_(std::string(MPTRACK_GOLDEN_DIR) + "/" + name + ".golden") {}

void GoldenFile::add_line(const char* label, char kind, std::uint64_t bits) {
  char buf[Label::kCapacity + 32];
  const std::size_t n = format_line(buf, sizeof buf, label, kind, bits);
  lines_.emplace_back(buf, n);
}

void GoldenFile::add_f32(const char* label, float v) { add_line(label, 'f', bits_of(v)); }

void GoldenFile::add_f64(const char* label, double v) { add_line(label, 'd', bits_of(v)); }

void GoldenFile::add_i64(const char* label, std::int64_t v) {
  add_line(label, 'i', static_cast<std::uint64_t>(v));
}

void GoldenFile::on_failure(const char* what) {
  std::fprintf(stderr, "golden %s: case precondition failed: %s\n", path_.c_str(), what);
}

bool GoldenFile::matches() const {
  if (failures() > 0) return false;
  if (env_set("MPTRACK_GOLDEN_REGENERATE")) {
    if (env_set("CI")) {
      std::fprintf(stderr, "golden: refusing to regenerate %s under CI\n", path_.c_str());
      return false;
    }
    std::ofstream out(path_, std::ios::trunc);
    for (const auto& line : lines_) out << line << '\n';
    std::fprintf(stderr, "golden: regenerated %s (%zu values)\n", path_.c_str(), lines_.size());
    return static_cast<bool>(out);
  }
  std::ifstream in(path_);
  if (!in) {
    std::fprintf(stderr, "golden: cannot read %s (regenerate with MPTRACK_GOLDEN_REGENERATE=1)\n",
                 path_.c_str());
    return false;
  }
  std::vector<std::string> expected;
  for (std::string line; std::getline(in, line);) expected.push_back(line);
  std::size_t mismatches = 0;
  const std::size_t n = expected.size() > lines_.size() ? expected.size() : lines_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::string want = i < expected.size() ? expected[i] : "<missing>";
    const std::string got = i < lines_.size() ? lines_[i] : "<missing>";
    if (want != got) {
      if (mismatches < 10) {
        std::fprintf(stderr, "golden %s line %zu: expected '%s', got '%s'\n", path_.c_str(), i + 1,
                     want.c_str(), got.c_str());
      }
      ++mismatches;
    }
  }
  if (mismatches > 0) {
    std::fprintf(stderr, "golden %s: %zu of %zu lines differ\n", path_.c_str(), mismatches, n);
  }
  return mismatches == 0;
}

}  // namespace mptrack::test
