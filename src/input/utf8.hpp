// UTF-8 validity of input text: Matrix Market files must be text, and a TOML document must be
// UTF-8 (TOML 1.0; see toml_preflight.hpp for why toml11 must not see anything else).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace railmodal::input {

// Byte offset of the first byte of `text` that does not start a well-formed UTF-8 sequence
// (truncated, overlong, a surrogate, above U+10FFFF, a stray continuation byte), or npos.
size_t invalid_utf8_at(std::string_view text);

// "0xdf": how an offending byte is named in error messages.
std::string byte_name(unsigned char b);

}  // namespace railmodal::input
