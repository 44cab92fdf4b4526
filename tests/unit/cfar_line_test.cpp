// cfar_line: the whole-line CFAR against Cfar::test() cell by cell.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <random>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/frontend/cfar_line.h"

namespace fe = mptrack::frontend;
using mptrack::Status;

namespace {

fe::Cfar make(fe::CfarType type, fe::CfarEdge edge, std::size_t guard = 2, std::size_t train = 8) {
  fe::CfarParams p;
  p.type = type;
  p.edge = edge;
  p.pfa = 1e-3;
  p.guard_cells = guard;
  p.training_cells = train;
  fe::Cfar c;
  REQUIRE(c.init(p) == Status::kOk);
  return c;
}

// Exponential noise rounded to 1/8 (many ties, which OS must handle) plus
// two strong cells.
std::vector<float> noisy_line(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::exponential_distribution<double> expo(1.0);
  std::vector<float> line(n);
  for (float& x : line) x = static_cast<float>(std::floor(expo(rng) * 8.0) / 8.0);
  line[n / 3] = 300.0f;
  line[n / 3 + 5] = 90.0f;
  return line;
}

constexpr fe::CfarEdge kEdges[] = {fe::CfarEdge::kSkip, fe::CfarEdge::kShift, fe::CfarEdge::kWrap};

}  // namespace

TEST_CASE("cfar_line OS equals Cfar::test bit for bit at every cell and edge policy") {
  for (fe::CfarEdge edge : kEdges) {
    for (std::size_t train : {std::size_t{1}, std::size_t{8}, std::size_t{24}}) {
      const fe::Cfar cfar = make(fe::CfarType::kOrderedStatistic, edge, 2, train);
      const std::vector<float> line = noisy_line(300, static_cast<unsigned>(train));
      std::vector<fe::CfarResult> out(line.size());
      std::size_t expected_hits = 0;
      const std::size_t hits = fe::cfar_line(cfar, line.data(), line.size(), out.data());
      for (std::size_t i = 0; i < line.size(); ++i) {
        const fe::CfarResult r = cfar.test(line.data(), line.size(), i);
        expected_hits += r.detected ? 1u : 0u;
        REQUIRE(out[i].tested == r.tested);
        REQUIRE(std::memcmp(&out[i].noise, &r.noise, sizeof(float)) == 0);
        REQUIRE(out[i].detected == r.detected);
      }
      CHECK(hits == expected_hits);
    }
  }
}

TEST_CASE("cfar_line OS equals Cfar::test bit for bit at the widest window over a long line") {
  // G = T = 64: the window spans 257 cells, and 2000 cells wrap the order
  // window's 512-slot table several times; every os_rank extreme too.
  for (fe::CfarEdge edge : kEdges) {
    for (std::size_t rank : {std::size_t{1}, std::size_t{64}, std::size_t{128}}) {
      fe::CfarParams p;
      p.type = fe::CfarType::kOrderedStatistic;
      p.edge = edge;
      p.pfa = 1e-3;
      p.guard_cells = 64;
      p.training_cells = 64;
      p.os_rank = rank;
      fe::Cfar cfar;
      REQUIRE(cfar.init(p) == Status::kOk);
      const std::vector<float> line = noisy_line(2000, static_cast<unsigned>(rank));
      std::vector<fe::CfarResult> out(line.size());
      (void)fe::cfar_line(cfar, line.data(), line.size(), out.data());
      for (std::size_t i = 0; i < line.size(); ++i) {
        const fe::CfarResult r = cfar.test(line.data(), line.size(), i);
        REQUIRE(out[i].tested == r.tested);
        REQUIRE(std::memcmp(&out[i].noise, &r.noise, sizeof(float)) == 0);
        REQUIRE(out[i].detected == r.detected);
      }
    }
  }
}

TEST_CASE("cfar_line CA/GO/SO noise is the window mean to float rounding, same cells tested") {
  for (fe::CfarType type : {fe::CfarType::kCellAveraging, fe::CfarType::kGreatestOf, fe::CfarType::kSmallestOf}) {
    for (fe::CfarEdge edge : kEdges) {
      const fe::Cfar cfar = make(type, edge);
      const std::vector<float> line = noisy_line(257, 7);
      std::vector<fe::CfarResult> out(line.size());
      (void)fe::cfar_line(cfar, line.data(), line.size(), out.data());
      for (std::size_t i = 0; i < line.size(); ++i) {
        const fe::CfarResult r = cfar.test(line.data(), line.size(), i);
        REQUIRE(out[i].tested == r.tested);
        if (!r.tested) continue;
        // Values are multiples of 1/8 below 2^9: the double sums are exact.
        float cells[fe::Cfar::kMaxTraining];
        const std::size_t n = cfar.gather_training(line.data(), line.size(), i, cells);
        double sl = 0.0;
        double sr = 0.0;
        for (std::size_t k = 0; k < n / 2; ++k) sl += static_cast<double>(cells[k]);
        for (std::size_t k = n / 2; k < n; ++k) sr += static_cast<double>(cells[k]);
        double mean = (sl + sr) / static_cast<double>(n);
        if (type == fe::CfarType::kGreatestOf) mean = std::max(sl, sr) / static_cast<double>(n / 2);
        if (type == fe::CfarType::kSmallestOf) mean = std::min(sl, sr) / static_cast<double>(n / 2);
        REQUIRE(out[i].noise == static_cast<float>(mean));  // one rounding of the exact mean
        REQUIRE(out[i].detected == (line[i] > cfar.alpha_f() * out[i].noise));
      }
    }
  }
}

TEST_CASE("cfar_line CA does not drift: far from a 1e7 cell, unit cells give exactly 1") {
  const fe::Cfar cfar = make(fe::CfarType::kCellAveraging, fe::CfarEdge::kShift, 2, 16);
  std::vector<float> line(65535, 1.0f);
  for (std::size_t i = 0; i < 2000; i += 3) line[i] = 1e7f + static_cast<float>(i);
  std::vector<fe::CfarResult> out(line.size());
  (void)fe::cfar_line(cfar, line.data(), line.size(), out.data());
  for (std::size_t i = 3000; i < line.size(); ++i) REQUIRE(out[i].noise == 1.0f);
  // A float running sum of the same line ends far from 1 (the drift avoided).
  float s = 0.0f;
  for (std::size_t k = 0; k < 32; ++k) s += line[k];
  for (std::size_t k = 32; k < line.size(); ++k) s += line[k] - line[k - 32];
  CHECK(s / 32.0f != 1.0f);
}

TEST_CASE("cfar_line falls back to Cfar::test on a line holding a NaN") {
  const fe::Cfar cfar = make(fe::CfarType::kCellAveraging, fe::CfarEdge::kShift);
  std::vector<float> line = noisy_line(100, 3);
  line[50] = std::nanf("");
  std::vector<fe::CfarResult> out(line.size());
  (void)fe::cfar_line(cfar, line.data(), line.size(), out.data());
  for (std::size_t i = 0; i < line.size(); ++i) {
    const fe::CfarResult r = cfar.test(line.data(), line.size(), i);
    REQUIRE(std::memcmp(&out[i].noise, &r.noise, sizeof(float)) == 0);
  }
}

TEST_CASE("cfar_line does not allocate (CA and OS)") {
  const std::vector<float> line = noisy_line(1024, 11);
  std::vector<fe::CfarResult> out(line.size());
  for (fe::CfarType type : {fe::CfarType::kCellAveraging, fe::CfarType::kOrderedStatistic}) {
    const fe::Cfar cfar = make(type, fe::CfarEdge::kShift);
    mptrack::test::NoAllocScope guard;
    const std::size_t hits = fe::cfar_line(cfar, line.data(), line.size(), out.data());
    CHECK(guard.allocations() == 0);
    CHECK(hits >= 1);
  }
}
