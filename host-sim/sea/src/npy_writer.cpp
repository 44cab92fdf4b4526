// NumPy .npy format 1.0: magic, version, header length (uint16 LE), an ASCII
// dict padded with spaces to a multiple of 64 bytes ending in '\n', raw data.
#include "mptrack/sea/npy_writer.h"

#include <cstdio>
#include <stdexcept>
#include <type_traits>

namespace mptrack::sea {

namespace {

template <class T>
const char* descr() {
  if constexpr (std::is_same_v<T, std::uint8_t>) return "|u1";
  if constexpr (std::is_same_v<T, std::int32_t>) return "<i4";
  if constexpr (std::is_same_v<T, float>) return "<f4";
}

bool little_endian() {
  const std::uint16_t x = 1;
  return *reinterpret_cast<const std::uint8_t*>(&x) == 1;
}

}  // namespace

template <class T>
void write_npy(const std::string& path, const std::vector<T>& data, const std::vector<std::uint64_t>& shape) {
  if (!little_endian()) throw std::runtime_error("write_npy: big-endian host not supported");
  std::string dims;
  for (std::size_t i = 0; i < shape.size(); ++i) dims += (i > 0 ? ", " : "") + std::to_string(shape[i]);
  if (shape.size() == 1) dims += ",";  // Python's one-element tuple
  std::string header = std::string("{'descr': '") + descr<T>() + "', 'fortran_order': False, 'shape': (" + dims + "), }";
  const std::size_t base = 10;  // magic (6) + version (2) + length (2)
  while ((base + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("cannot write " + path);
  const unsigned char magic[8] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};
  const unsigned char len[2] = {static_cast<unsigned char>(header.size() & 0xff),
                                static_cast<unsigned char>(header.size() >> 8)};
  bool ok = std::fwrite(magic, 1, 8, f) == 8 && std::fwrite(len, 1, 2, f) == 2 &&
            std::fwrite(header.data(), 1, header.size(), f) == header.size();
  if (!data.empty()) ok = ok && std::fwrite(data.data(), sizeof(T), data.size(), f) == data.size();
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) throw std::runtime_error("write failed: " + path);
}

template void write_npy<std::uint8_t>(const std::string&, const std::vector<std::uint8_t>&,
                                      const std::vector<std::uint64_t>&);
template void write_npy<std::int32_t>(const std::string&, const std::vector<std::int32_t>&,
                                      const std::vector<std::uint64_t>&);
template void write_npy<float>(const std::string&, const std::vector<float>&, const std::vector<std::uint64_t>&);

}  // namespace mptrack::sea
