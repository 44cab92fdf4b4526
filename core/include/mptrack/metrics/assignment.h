// Optimal linear assignment (minimum-cost bipartite matching) for a
// rectangular cost matrix, without heap.
//
// Algorithm: the shortest-augmenting-path form of the Hungarian method
// (Kuhn-Munkres with Jonker-Volgenant style potentials and a dense Dijkstra
// per row), O(k^2 l) for a k x l problem with k <= l. Each row is added in
// turn; a Dijkstra over reduced costs c(i,j) - u(i) - v(j) finds the cheapest
// augmenting path, and the dual potentials u, v are updated so that reduced
// costs stay >= 0 (complementary slackness proves optimality at the end).
//
// Rectangular problems: min(rows, cols) pairs are assigned, every element of
// the smaller side gets a partner. When rows > cols the solver runs on the
// transpose (same storage, swapped indexing) so the inner loop always spans
// the larger side.
//
// Determinism: fixed loop order; in every Dijkstra step the lowest column
// index wins among equal reduced costs (strict '<'), so the result is a
// pure function of the cost bits on every target.
//
// Memory: the cost matrix and all scratch are members (about
// MaxRows * MaxCols * sizeof(T) bytes): place large solvers in static
// storage or inside the owning object, never on a small stack.
//
//   AssignmentSolver<float, 64> solver;      // e.g. a member
//   MPTRACK_TRY(solver.resize(n_rows, n_cols));
//   solver.cost(i, j) = ...;                 // every entry, finite
//   MPTRACK_TRY(solver.solve());
//   solver.row_assignment(i)                 // column or -1
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "mptrack/status.h"
#include "mptrack/validate.h"

namespace mptrack {

template <class T, std::size_t MaxRows, std::size_t MaxCols = MaxRows>
class AssignmentSolver {
  static_assert(MaxRows >= 1 && MaxCols >= 1, "AssignmentSolver needs non-zero caps");
  static_assert(MaxRows <= 65535 && MaxCols <= 65535, "indices are reported as int32");

 public:
  static constexpr std::size_t kMaxRows = MaxRows;
  static constexpr std::size_t kMaxCols = MaxCols;
  /// Larger side: the algorithm's column count after a possible transpose.
  static constexpr std::size_t kMaxDim = MaxRows > MaxCols ? MaxRows : MaxCols;
  /// Value of row_assignment()/col_assignment() for "no partner".
  static constexpr std::int32_t kUnassigned = -1;

  /// Sets the problem size (entries keep stale values: write all of them).
  /// kCapacityExceeded (size unchanged) if rows > MaxRows or cols > MaxCols.
  Status resize(std::size_t rows, std::size_t cols) {
    if (rows > MaxRows || cols > MaxCols) return Status::kCapacityExceeded;
    rows_ = rows;
    cols_ = cols;
    solved_ = false;
    return Status::kOk;
  }

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }

  /// Cost of assigning row r to column c (r < rows(), c < cols(); unchecked).
  T& cost(std::size_t r, std::size_t c) { return cost_[r * MaxCols + c]; }
  const T& cost(std::size_t r, std::size_t c) const { return cost_[r * MaxCols + c]; }

  /// Solves the problem set by resize() and cost(). kInvalidInput if any
  /// entry is NaN/Inf (nothing assigned then); kNumericalError if the
  /// augmentation could not proceed (cannot happen with finite costs; kept
  /// as a guard instead of an assert).
  Status solve() {
    solved_ = false;
    total_cost_ = T(0);
    for (std::size_t r = 0; r < rows_; ++r) row_to_col_[r] = kUnassigned;
    for (std::size_t c = 0; c < cols_; ++c) col_to_row_[c] = kUnassigned;
    for (std::size_t r = 0; r < rows_; ++r) {
      for (std::size_t c = 0; c < cols_; ++c) {
        if (!is_finite(cost(r, c))) return Status::kInvalidInput;
      }
    }
    if (rows_ == 0 || cols_ == 0) {
      solved_ = true;
      return Status::kOk;
    }
    const bool transposed = rows_ > cols_;
    const std::size_t n = transposed ? cols_ : rows_;  // algorithm rows (smaller side)
    const std::size_t m = transposed ? rows_ : cols_;  // algorithm columns
    MPTRACK_TRY(run(n, m, transposed));
    // p_[j] = algorithm row matched to algorithm column j (1-based, 0 = none).
    for (std::size_t j = 1; j <= m; ++j) {
      if (p_[j] == 0) continue;
      const std::size_t a_row = p_[j] - 1;
      const std::size_t a_col = j - 1;
      const std::size_t r = transposed ? a_col : a_row;
      const std::size_t c = transposed ? a_row : a_col;
      row_to_col_[r] = static_cast<std::int32_t>(c);
      col_to_row_[c] = static_cast<std::int32_t>(r);
    }
    // Total in row order (fixed summation order, independent of the path).
    for (std::size_t r = 0; r < rows_; ++r) {
      if (row_to_col_[r] != kUnassigned) {
        total_cost_ += cost(r, static_cast<std::size_t>(row_to_col_[r]));
      }
    }
    solved_ = true;
    return Status::kOk;
  }

  /// True after a successful solve() (until the next resize()).
  bool solved() const { return solved_; }
  /// Column assigned to row r, or kUnassigned.
  std::int32_t row_assignment(std::size_t r) const { return row_to_col_[r]; }
  /// Row assigned to column c, or kUnassigned.
  std::int32_t col_assignment(std::size_t c) const { return col_to_row_[c]; }
  /// Sum of the assigned entries, summed in row order.
  T total_cost() const { return total_cost_; }

 private:
  // Entry (i, j) of the algorithm's n x m problem, 0-based.
  T at(std::size_t i, std::size_t j, bool transposed) const {
    return transposed ? cost(j, i) : cost(i, j);
  }

  // Shortest augmenting path Hungarian method on an n x m problem, n <= m.
  // Arrays are 1-based with index 0 as the virtual source column.
  Status run(std::size_t n, std::size_t m, bool transposed) {
    const T kInf = std::numeric_limits<T>::infinity();
    for (std::size_t j = 0; j <= m; ++j) {
      v_[j] = T(0);
      p_[j] = 0;
      way_[j] = 0;
    }
    for (std::size_t i = 0; i <= n; ++i) u_[i] = T(0);

    for (std::size_t i = 1; i <= n; ++i) {
      p_[0] = i;
      std::size_t j0 = 0;
      for (std::size_t j = 0; j <= m; ++j) {
        minv_[j] = kInf;
        used_[j] = false;
      }
      do {
        used_[j0] = true;
        const std::size_t i0 = p_[j0];
        T delta = kInf;
        std::size_t j1 = 0;
        for (std::size_t j = 1; j <= m; ++j) {
          if (used_[j]) continue;
          const T reduced = at(i0 - 1, j - 1, transposed) - u_[i0] - v_[j];
          if (reduced < minv_[j]) {
            minv_[j] = reduced;
            way_[j] = j0;
          }
          if (minv_[j] < delta) {  // strict: lowest index wins ties
            delta = minv_[j];
            j1 = j;
          }
        }
        if (j1 == 0) return Status::kNumericalError;  // no reachable free column
        for (std::size_t j = 0; j <= m; ++j) {
          if (used_[j]) {
            u_[p_[j]] += delta;
            v_[j] -= delta;
          } else {
            minv_[j] -= delta;
          }
        }
        j0 = j1;
      } while (p_[j0] != 0);
      // Flip the augmenting path back to the source.
      do {
        const std::size_t j1 = way_[j0];
        p_[j0] = p_[j1];
        j0 = j1;
      } while (j0 != 0);
    }
    return Status::kOk;
  }

  std::array<T, MaxRows * MaxCols> cost_{};  ///< row-major, stride MaxCols
  std::array<std::int32_t, MaxRows> row_to_col_{};
  std::array<std::int32_t, MaxCols> col_to_row_{};
  // Scratch of the algorithm (1-based, + 1 for the virtual column 0).
  std::array<T, kMaxDim + 1> u_{};           ///< row potentials
  std::array<T, kMaxDim + 1> v_{};           ///< column potentials
  std::array<T, kMaxDim + 1> minv_{};        ///< tentative path lengths
  std::array<std::size_t, kMaxDim + 1> p_{};    ///< row matched to column j (0 = none)
  std::array<std::size_t, kMaxDim + 1> way_{};  ///< predecessor column on the path
  std::array<bool, kMaxDim + 1> used_{};
  std::size_t rows_ = 0;
  std::size_t cols_ = 0;
  T total_cost_ = T(0);
  bool solved_ = false;
};

}  // namespace mptrack
