#pragma once
// Little-endian binary output for the mesh writers (STL, PLY); private to
// src/io. Bytes are assembled by shifts, so the output is little-endian
// whatever the machine's byte order.

#include <cstdint>
#include <cstring>
#include <string>

namespace casteljau::io_detail {

inline void append_le32(std::string& out, std::uint32_t value) {
  for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((value >> (8 * b)) & 0xFFu));
}

inline void append_le16(std::string& out, std::uint16_t value) {
  out.push_back(static_cast<char>(value & 0xFFu));
  out.push_back(static_cast<char>((value >> 8) & 0xFFu));
}

inline void append_float(std::string& out, float value) {
  std::uint32_t bits = 0;
  static_assert(sizeof bits == sizeof value);
  std::memcpy(&bits, &value, sizeof bits);
  append_le32(out, bits);
}

inline void append_double(std::string& out, double value) {
  std::uint64_t bits = 0;
  static_assert(sizeof bits == sizeof value);
  std::memcpy(&bits, &value, sizeof bits);
  for (int b = 0; b < 8; ++b) out.push_back(static_cast<char>((bits >> (8 * b)) & 0xFFu));
}

}  // namespace casteljau::io_detail
