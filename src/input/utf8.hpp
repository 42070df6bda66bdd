// UTF-8 validity of input text. Both readers need it: Matrix Market comments must be text,
// and a TOML document must be UTF-8 (TOML 1.0, "Spec") — besides, Debian's toml11 3.7.1
// reads past its buffer when it reports invalid UTF-8 inside a literal string, so the TOML
// reader must never hand it such bytes.
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
