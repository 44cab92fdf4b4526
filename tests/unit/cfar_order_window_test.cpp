// CfarOrderWindow: the k-th smallest of a sliding set against std::nth_element.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <random>
#include <vector>

#include "mptrack/frontend/cfar_order_window.h"

namespace fe = mptrack::frontend;

namespace {

// k-th smallest (1-based) of v, by the reference selection Cfar::test() uses.
float kth_reference(std::vector<float> v, std::size_t k) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k - 1), v.end());
  return v[k - 1];
}

}  // namespace

TEST_CASE("CfarOrderWindow keeps the k-th smallest under random replacements, ties included") {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> level(0, 20);  // 21 levels: many ties
  for (std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{16}, std::size_t{128}}) {
    for (std::size_t k : {std::size_t{1}, (n + 1) / 2, n}) {
      // Cells at positions base..base+n-1; each step the oldest leaves and
      // position base+n enters (a window sliding along a line).
      std::vector<float> cells(n);
      std::vector<std::size_t> pos(n);
      for (std::size_t i = 0; i < n; ++i) {
        cells[i] = static_cast<float>(level(rng)) * 0.25f;
        pos[i] = 1000 + i;
      }
      fe::CfarOrderWindow w;
      w.reset(cells.data(), pos.data(), n, k);
      REQUIRE(w.kth() == kth_reference(cells, k));
      for (std::size_t step = 0; step < 1500; ++step) {
        const std::size_t oldest = step % n;  // cells[oldest] holds position 1000 + step
        const float x = static_cast<float>(level(rng)) * 0.25f;
        w.replace(1000 + step, 1000 + step + n, x);
        cells[oldest] = x;
        const float got = w.kth();
        const float want = kth_reference(cells, k);
        REQUIRE(std::memcmp(&got, &want, sizeof(float)) == 0);
      }
    }
  }
}
