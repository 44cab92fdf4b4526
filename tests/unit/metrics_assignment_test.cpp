#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "alloc_guard.h"
#include "mptrack/metrics/assignment.h"

using mptrack::AssignmentSolver;
using mptrack::Status;

namespace {

// Deterministic LCG (Numerical Recipes constants); uniform in [0, 1).
struct Lcg {
  std::uint32_t state;
  double next() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  }
};

// Minimum over all injections of the smaller side into the larger one.
double brute_force_min(const std::vector<std::vector<double>>& c) {
  const std::size_t rows = c.size();
  const std::size_t cols = rows == 0 ? 0 : c[0].size();
  if (rows == 0 || cols == 0) return 0.0;
  const bool transposed = rows > cols;
  const std::size_t k = transposed ? cols : rows;
  const std::size_t l = transposed ? rows : cols;
  std::vector<std::size_t> perm(l);
  for (std::size_t j = 0; j < l; ++j) perm[j] = j;
  double best = std::numeric_limits<double>::infinity();
  do {
    double s = 0.0;
    for (std::size_t i = 0; i < k; ++i) s += transposed ? c[perm[i]][i] : c[i][perm[i]];
    best = std::min(best, s);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

// Checks the solver's assignment is a valid matching of min(rows, cols)
// pairs whose cost, summed in row order in the solver's scalar, is exactly
// total_cost().
template <class Solver>
void check_consistent(const Solver& s) {
  const std::size_t expected_pairs = std::min(s.rows(), s.cols());
  std::size_t pairs = 0;
  auto sum = s.total_cost() - s.total_cost();
  for (std::size_t r = 0; r < s.rows(); ++r) {
    const std::int32_t c = s.row_assignment(r);
    if (c < 0) continue;
    ++pairs;
    CHECK(s.col_assignment(static_cast<std::size_t>(c)) == static_cast<std::int32_t>(r));
    sum += s.cost(r, static_cast<std::size_t>(c));
  }
  CHECK(pairs == expected_pairs);
  CHECK(s.total_cost() == sum);
}

}  // namespace

TEST_CASE("assignment matches brute force on random square matrices up to 7x7") {
  auto solver = std::make_unique<AssignmentSolver<double, 7>>();
  Lcg rng{12345u};
  for (std::size_t n = 1; n <= 7; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::vector<double>> c(n, std::vector<double>(n));
      REQUIRE(solver->resize(n, n) == Status::kOk);
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
          // Coarse integer costs in half the trials force many ties.
          c[i][j] = trial % 2 == 0 ? 100.0 * rng.next() - 30.0 : static_cast<double>(
                                                                    static_cast<int>(4.0 * rng.next()));
          solver->cost(i, j) = c[i][j];
        }
      }
      REQUIRE(solver->solve() == Status::kOk);
      CHECK(solver->total_cost() == doctest::Approx(brute_force_min(c)).epsilon(1e-12));
      check_consistent(*solver);
    }
  }
}

TEST_CASE("assignment matches brute force on rectangular matrices, both orientations") {
  auto solver = std::make_unique<AssignmentSolver<double, 7, 7>>();
  Lcg rng{777u};
  for (std::size_t rows = 1; rows <= 7; ++rows) {
    for (std::size_t cols = 1; cols <= 7; ++cols) {
      if (rows == cols) continue;
      for (int trial = 0; trial < 5; ++trial) {
        std::vector<std::vector<double>> c(rows, std::vector<double>(cols));
        REQUIRE(solver->resize(rows, cols) == Status::kOk);
        for (std::size_t i = 0; i < rows; ++i) {
          for (std::size_t j = 0; j < cols; ++j) {
            c[i][j] = 50.0 * rng.next();
            solver->cost(i, j) = c[i][j];
          }
        }
        REQUIRE(solver->solve() == Status::kOk);
        CHECK(solver->total_cost() == doctest::Approx(brute_force_min(c)).epsilon(1e-12));
        check_consistent(*solver);
      }
    }
  }
}

TEST_CASE("assignment in float agrees with the double brute force") {
  auto solver = std::make_unique<AssignmentSolver<float, 6, 9>>();
  Lcg rng{4242u};
  for (int trial = 0; trial < 30; ++trial) {
    const std::size_t rows = 1 + static_cast<std::size_t>(trial % 6);
    const std::size_t cols = 1 + static_cast<std::size_t>((trial * 5) % 7);
    std::vector<std::vector<double>> c(rows, std::vector<double>(cols));
    REQUIRE(solver->resize(rows, cols) == Status::kOk);
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::size_t j = 0; j < cols; ++j) {
        const float v = static_cast<float>(20.0 * rng.next());
        c[i][j] = static_cast<double>(v);
        solver->cost(i, j) = v;
      }
    }
    REQUIRE(solver->solve() == Status::kOk);
    CHECK(static_cast<double>(solver->total_cost()) ==
          doctest::Approx(brute_force_min(c)).epsilon(1e-5));
    check_consistent(*solver);
  }
}

TEST_CASE("assignment of a hand-made 3x3 problem") {
  // Every row prefers column 0; the optimum 0->1, 1->0, 2->2 costs
  // 2 + 1 + 3 = 6 (identity: 1 + 5 + 3 = 9; the other four permutations >= 19).
  AssignmentSolver<double, 3> s;
  const double c[3][3] = {{1, 2, 9}, {1, 5, 9}, {1, 9, 3}};
  REQUIRE(s.resize(3, 3) == Status::kOk);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) s.cost(i, j) = c[i][j];
  REQUIRE(s.solve() == Status::kOk);
  CHECK(s.row_assignment(0) == 1);
  CHECK(s.row_assignment(1) == 0);
  CHECK(s.row_assignment(2) == 2);
  CHECK(s.total_cost() == 6.0);
}

TEST_CASE("assignment ties resolve to the lowest index: all-equal costs give the identity") {
  AssignmentSolver<float, 5> s;
  REQUIRE(s.resize(5, 5) == Status::kOk);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 5; ++j) s.cost(i, j) = 2.0f;
  REQUIRE(s.solve() == Status::kOk);
  for (std::size_t i = 0; i < 5; ++i) CHECK(s.row_assignment(i) == static_cast<std::int32_t>(i));
  CHECK(s.total_cost() == 10.0f);
}

TEST_CASE("assignment with a zero dimension assigns nothing and costs 0") {
  AssignmentSolver<float, 4> s;
  for (const auto& dims : {std::pair<std::size_t, std::size_t>{0, 0}, {0, 3}, {3, 0}}) {
    REQUIRE(s.resize(dims.first, dims.second) == Status::kOk);
    for (std::size_t i = 0; i < dims.first; ++i)
      for (std::size_t j = 0; j < dims.second; ++j) s.cost(i, j) = 1.0f;
    CHECK(s.solve() == Status::kOk);
    CHECK(s.solved());
    CHECK(s.total_cost() == 0.0f);
    for (std::size_t i = 0; i < dims.first; ++i) CHECK(s.row_assignment(i) == -1);
    for (std::size_t j = 0; j < dims.second; ++j) CHECK(s.col_assignment(j) == -1);
  }
}

TEST_CASE("assignment rejects oversize problems and non-finite costs") {
  AssignmentSolver<float, 4, 3> s;
  CHECK(s.resize(5, 3) == Status::kCapacityExceeded);
  CHECK(s.resize(4, 4) == Status::kCapacityExceeded);
  REQUIRE(s.resize(2, 2) == Status::kOk);
  s.cost(0, 0) = 1.0f;
  s.cost(0, 1) = std::numeric_limits<float>::quiet_NaN();
  s.cost(1, 0) = 1.0f;
  s.cost(1, 1) = 1.0f;
  CHECK(s.solve() == Status::kInvalidInput);
  CHECK_FALSE(s.solved());
  CHECK(s.row_assignment(0) == -1);
  s.cost(0, 1) = std::numeric_limits<float>::infinity();
  CHECK(s.solve() == Status::kInvalidInput);
}

TEST_CASE("assignment solve allocates nothing (64 x 96)") {
  auto s = std::make_unique<AssignmentSolver<float, 64, 96>>();
  Lcg rng{99u};
  REQUIRE(s->resize(64, 96) == Status::kOk);
  for (std::size_t i = 0; i < 64; ++i)
    for (std::size_t j = 0; j < 96; ++j) s->cost(i, j) = static_cast<float>(rng.next());
  mptrack::test::NoAllocScope guard;
  const Status st = s->solve();
  CHECK(guard.allocations() == 0);
  CHECK(st == Status::kOk);
  check_consistent(*s);
}
