#include "golden_sink.h"

namespace mptrack::test {

namespace {
constexpr char kHex[] = "0123456789abcdef";

// Appends s to out[n..cap-1]; returns the new length (truncates).
std::size_t put(char* out, std::size_t cap, std::size_t n, const char* s) {
  while (*s != '\0' && n + 1 < cap) out[n++] = *s++;
  out[n] = '\0';
  return n;
}

// Decimal digits of v (no sign), most significant first, into buf; returns count.
int decimal(std::uint64_t v, char* buf) {
  char rev[24];
  int n = 0;
  do {
    rev[n++] = static_cast<char>('0' + static_cast<int>(v % 10u));
    v /= 10u;
  } while (v != 0u);
  for (int i = 0; i < n; ++i) buf[i] = rev[n - 1 - i];
  buf[n] = '\0';
  return n;
}
}  // namespace

void Label::append(const char* s) {
  while (*s != '\0') {
    if (size_ + 1 >= kCapacity) {
      truncated_ = true;
      break;
    }
    text_[size_++] = *s++;
  }
  text_[size_] = '\0';
}

void Label::append_int(std::int64_t v) {
  char buf[24];
  if (v < 0) append("-");
  // Magnitude as unsigned: well defined for INT64_MIN too.
  const std::uint64_t mag = v < 0 ? 0u - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  decimal(mag, buf);
  append(buf);
}

void Label::append_hex(std::uint64_t v, int digits) {
  char buf[17];
  for (int i = 0; i < digits; ++i) {
    buf[i] = kHex[(v >> (4 * (digits - 1 - i))) & 0xFu];
  }
  buf[digits] = '\0';
  append(buf);
}

Label Label::bits(float v) const {
  Label r = *this;
  r.append_hex(bits_of(v), 8);
  return r;
}

Label Label::bits(double v) const {
  Label r = *this;
  r.append_hex(bits_of(v), 16);
  return r;
}

std::size_t format_line(char* out, std::size_t cap, const char* label, char kind, std::uint64_t bits) {
  Label tail;
  if (kind == 'f') {
    tail.append(" f32 ");
    tail.append_hex(bits, 8);
  } else if (kind == 'd') {
    tail.append(" f64 ");
    tail.append_hex(bits, 16);
  } else {
    tail.append(" i64 ");
    tail.append_int(static_cast<std::int64_t>(bits));
  }
  std::size_t n = put(out, cap, 0, label);
  return put(out, cap, n, tail.c_str());
}

}  // namespace mptrack::test
