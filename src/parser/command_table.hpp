#pragma once
// The one table of words drycut knows: which commands, procedures, G codes and addresses the
// interpreter models, and which are valid SINUMERIK but not modelled (those give warning 990002
// and are dropped from the block). Anything else is a programming error.
#include <string_view>

namespace drycut::parser {

enum class Support : uint8_t { Unknown, Modelled, NotModelled };

// Commands and procedures by upper-case name (ASPLINE, CYCLE832, TRAORI, CYCLE81 ...).
Support command_support(std::string_view upper_name);
// G codes by number.
Support g_code_support(int64_t code);
// Addresses that carry a value: X Y Z A B C ... F S D H T, I1 J1 K1, PW SD PL CR AR AP RP TURN.
bool is_address(std::string_view upper_name);
// Closest known command or keyword within a small edit distance ("ASPLIN" -> "ASPLINE"), or
// empty. Used to tell a misspelled word from an unknown subprogram.
std::string_view near_miss(std::string_view upper_name);

}  // namespace drycut::parser
