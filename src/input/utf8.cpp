#include "input/utf8.hpp"

#include <cstdint>

namespace railmodal::input {

size_t invalid_utf8_at(std::string_view text) {
  for (size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x80) {
      ++i;
      continue;
    }
    // Lead byte: length and the smallest code point it may encode (no overlong forms).
    size_t length = 0;
    uint32_t code = 0, least = 0;
    if ((b & 0xe0) == 0xc0) length = 2, code = b & 0x1f, least = 0x80;
    else if ((b & 0xf0) == 0xe0) length = 3, code = b & 0x0f, least = 0x800;
    else if ((b & 0xf8) == 0xf0) length = 4, code = b & 0x07, least = 0x10000;
    bool ok = length > 0 && i + length <= text.size();
    for (size_t k = 1; ok && k < length; ++k) {
      const auto c = static_cast<unsigned char>(text[i + k]);
      ok = (c & 0xc0) == 0x80;
      code = (code << 6) | (c & 0x3f);
    }
    if (!ok || code < least || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return i;
    i += length;
  }
  return std::string_view::npos;
}

std::string byte_name(unsigned char b) {
  static const char* hex = "0123456789abcdef";
  return std::string("0x") + hex[b >> 4] + hex[b & 15];
}

}  // namespace railmodal::input
