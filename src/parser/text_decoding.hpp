#pragma once
// Shop files come as UTF-8 or as Latin-1/CP1252 (German comments with umlauts). Blocks are kept
// as UTF-8 inside drycut, so every line is decoded once when it is read.
#include <string>
#include <string_view>

namespace drycut::parser {

// True when every byte is 7-bit ASCII (the common case: nothing to decode).
bool is_ascii(std::string_view bytes);

// Decodes one line to UTF-8 into `out` (replacing its content): a line that is valid UTF-8 is
// copied as is, any other line is read as CP1252 (a superset of Latin-1 for printable bytes).
void decode_line_to_utf8(std::string_view bytes, std::string& out);

}  // namespace drycut::parser
