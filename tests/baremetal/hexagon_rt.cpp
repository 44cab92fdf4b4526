// Minimal runtime for the golden runner on Hexagon under qemu-hexagon
// (Linux user mode), in place of the C library and compiler-rt that Debian
// does not ship for Hexagon:
//   - _start, console output and exit through Linux system calls (trap0);
//   - mem* functions;
//   - the compiler helpers clang calls on Hexagon v68: unsigned 32-bit
//     division, and IEEE-754 double division and square root (correctly
//     rounded to nearest even, in integer arithmetic), from which float
//     division and sqrtf follow exactly (a double result rounded to float is
//     the correctly rounded float result for / and sqrt: 53 >= 2*24 + 2).
// Compiled with -ffreestanding -fno-builtin so no loop here becomes a call
// to itself. Not a general libc: only what the golden runner links.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "semihost.h"

using u32 = std::uint32_t;
using u64 = std::uint64_t;

// ---- start-up, console, exit (Linux generic system call numbers) ----------
extern "C" int app_main();
extern "C" [[noreturn]] void mptrack_hexagon_start() {
  static_cast<void>(app_main());
  mptrack::baremetal::sh_exit(false);  // app_main exits itself
}
__asm__(
    ".text\n"
    ".global _start\n"
    ".type _start, @function\n"
    "_start:\n"
    "  r29 = and(r29, #-8)\n"
    "  r30 = #0\n"
    "  call mptrack_hexagon_start\n");

namespace {
long linux_syscall3(long nr, long a, long b, long c) {
  register long r0 __asm__("r0") = a;
  register long r1 __asm__("r1") = b;
  register long r2 __asm__("r2") = c;
  register long r6 __asm__("r6") = nr;
  __asm__ volatile("trap0(#1)" : "+r"(r0) : "r"(r1), "r"(r2), "r"(r6) : "memory");
  return r0;
}
constexpr long kSysWrite = 64;
constexpr long kSysExitGroup = 94;
}  // namespace

namespace mptrack::baremetal {
void sh_write(const char* s) {
  std::size_t n = 0;
  while (s[n] != '\0') ++n;
  static_cast<void>(linux_syscall3(kSysWrite, 1, reinterpret_cast<long>(s), static_cast<long>(n)));
}
void sh_exit(bool ok) {
  static_cast<void>(linux_syscall3(kSysExitGroup, ok ? 0 : 1, 0, 0));
  for (;;) {
  }
}
}  // namespace mptrack::baremetal

// ---- memory ----------------------------------------------------------------
extern "C" {
void* memcpy(void* dst, const void* src, std::size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  const auto* s = static_cast<const unsigned char*>(src);
  for (std::size_t i = 0; i < n; ++i) d[i] = s[i];
  return dst;
}
void* __hexagon_memcpy_likely_aligned_min32bytes_mult8bytes(void* dst, const void* src, std::size_t n) {
  return memcpy(dst, src, n);
}
void* memmove(void* dst, const void* src, std::size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  const auto* s = static_cast<const unsigned char*>(src);
  if (d < s) {
    for (std::size_t i = 0; i < n; ++i) d[i] = s[i];
  } else {
    for (std::size_t i = n; i > 0; --i) d[i - 1] = s[i - 1];
  }
  return dst;
}
void* memset(void* dst, int c, std::size_t n) {
  auto* d = static_cast<unsigned char*>(dst);
  for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<unsigned char>(c);
  return dst;
}
int memcmp(const void* a, const void* b, std::size_t n) {
  const auto* x = static_cast<const unsigned char*>(a);
  const auto* y = static_cast<const unsigned char*>(b);
  for (std::size_t i = 0; i < n; ++i) {
    if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
  }
  return 0;
}
std::size_t strlen(const char* s) {
  std::size_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}
char* strchr(const char* s, int c) {
  for (;; ++s) {
    if (*s == static_cast<char>(c)) return const_cast<char*>(s);
    if (*s == '\0') return nullptr;
  }
}

// ---- integer division ------------------------------------------------------
static u32 udivmod32(u32 n, u32 d, u32* rem) {
  u32 q = 0;
  u32 r = 0;
  for (int i = 31; i >= 0; --i) {
    r = (r << 1) | ((n >> i) & 1u);
    if (r >= d) {
      r -= d;
      q |= 1u << i;
    }
  }
  *rem = r;
  return q;
}
u32 __hexagon_udivsi3(u32 n, u32 d) {
  u32 r;
  return udivmod32(n, d, &r);
}
u32 __hexagon_umodsi3(u32 n, u32 d) {
  u32 r;
  udivmod32(n, d, &r);
  return r;
}
}  // extern "C"

// ---- IEEE-754 binary64 division and square root ------------------------------
namespace {
constexpr u64 kSign = 0x8000000000000000ull;
constexpr u64 kFrac = 0x000FFFFFFFFFFFFFull;
constexpr u64 kHidden = 0x0010000000000000ull;
constexpr u64 kInf = 0x7FF0000000000000ull;
constexpr u64 kQuiet = 0x0008000000000000ull;
constexpr u64 kDefaultNan = 0x7FF8000000000000ull;

u64 bits(double x) {
  u64 u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}
double from_bits(u64 u) {
  double x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

// Mantissa with the hidden bit at 52 and its exponent (biased; subnormals
// normalised, so it may go below 1). x must be finite and non-zero.
void unpack(u64 x, u64& m, int& e) {
  m = x & kFrac;
  e = static_cast<int>((x >> 52) & 0x7FF);
  if (e == 0) {
    e = 1;
    while ((m & kHidden) == 0) {
      m <<= 1;
      --e;
    }
  } else {
    m |= kHidden;
  }
}

// q: 55 significant bits (53 + guard + round) of a positive result with
// biased exponent e (for q in [2^54, 2^55)); sticky: any lower bit set.
u64 round_pack(u64 sign, u64 q, int e, bool sticky) {
  if (e <= 0) {  // subnormal: shift right, keeping what falls off as sticky
    const int shift = 1 - e;
    if (shift >= 60) {
      sticky = sticky || q != 0;
      q = 0;
    } else {
      sticky = sticky || (q & ((u64{1} << shift) - 1)) != 0;
      q >>= shift;
    }
    e = 0;
  }
  u64 mant = q >> 2;
  const bool guard = ((q >> 1) & 1u) != 0;
  const bool rest = (q & 1u) != 0 || sticky;
  if (guard && (rest || (mant & 1u) != 0)) ++mant;
  if (e == 0) return sign | mant;  // a carry into bit 52 gives the smallest normal
  if (mant == (kHidden << 1)) {
    mant >>= 1;
    ++e;
  }
  if (e >= 0x7FF) return sign | kInf;
  return sign | (static_cast<u64>(e) << 52) | (mant & kFrac);
}

u64 div_bits(u64 a, u64 b) {
  const u64 sign = (a ^ b) & kSign;
  const u64 aa = a & ~kSign;
  const u64 ab = b & ~kSign;
  if (aa > kInf) return a | kQuiet;
  if (ab > kInf) return b | kQuiet;
  if (aa == kInf) return ab == kInf ? kDefaultNan : sign | kInf;
  if (ab == kInf) return sign;
  if (ab == 0) return aa == 0 ? kDefaultNan : sign | kInf;
  if (aa == 0) return sign;
  u64 ma, mb;
  int ea, eb;
  unpack(aa, ma, ea);
  unpack(ab, mb, eb);
  int e = ea - eb + 1023;
  if (ma < mb) {
    ma <<= 1;
    --e;
  }
  u64 q = 0;
  u64 r = ma;  // in [mb, 2 mb)
  for (int i = 0; i < 55; ++i) {
    q <<= 1;
    if (r >= mb) {
      r -= mb;
      q |= 1u;
    }
    r <<= 1;
  }
  return round_pack(sign, q, e, r != 0);
}

u64 sqrt_bits(u64 a) {
  const u64 aa = a & ~kSign;
  if (aa > kInf) return a | kQuiet;
  if (aa == 0) return a;  // +-0
  if ((a & kSign) != 0) return kDefaultNan;
  if (aa == kInf) return a;
  u64 m;
  int e;
  unpack(aa, m, e);
  int ue = e - 1023;  // value = m * 2^(ue - 52)
  if ((ue & 1) != 0) {
    m <<= 1;
    --ue;
  }
  // Root of R = m * 2^56 (110 bits), two bits at a time: 55 root bits.
  u64 q = 0;
  u64 r = 0;
  for (int i = 54; i >= 0; --i) {
    const int shift = 2 * i - 56;
    const u64 pair = shift >= 0 ? (m >> shift) & 3u : 0u;
    r = (r << 2) | pair;
    const u64 t = (q << 2) | 1u;
    if (r >= t) {
      r -= t;
      q = (q << 1) | 1u;
    } else {
      q <<= 1;
    }
  }
  return round_pack(0, q, ue / 2 + 1023, r != 0);
}
}  // namespace

extern "C" {
double __hexagon_divdf3(double a, double b) { return from_bits(div_bits(bits(a), bits(b))); }
float __hexagon_divsf3(float a, float b) {
  return static_cast<float>(__hexagon_divdf3(static_cast<double>(a), static_cast<double>(b)));
}
double sqrt(double x) { return from_bits(sqrt_bits(bits(x))); }
float sqrtf(float x) { return static_cast<float>(sqrt(static_cast<double>(x))); }
}  // extern "C"
