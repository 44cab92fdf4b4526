// Minimal NumPy .npy (format 1.0) writer: little-endian C-order arrays that
// numpy.load reads directly (docs/algorithms/sea_clutter.md §Dataset).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mptrack::sea {

/// Writes `data` (row-major, shape `shape`) to `path`; dtype from T
/// (uint8, int32, float32). Throws std::runtime_error on I/O failure.
template <class T>
void write_npy(const std::string& path, const std::vector<T>& data, const std::vector<std::uint64_t>& shape);

}  // namespace mptrack::sea
