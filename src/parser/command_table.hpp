#pragma once
// The one table of words drycut knows: which commands, procedures, G codes and addresses the
// interpreter models, and which are valid SINUMERIK but not modelled (those give warning 990002
// and are dropped from the block). Anything else is a programming error.
#include <span>
#include <string_view>

namespace drycut::parser {

// NoEffect: valid, and correctly modelled by doing nothing in a dry run (SBLOF, DISPLON ...).
enum class Support : uint8_t { Unknown, Modelled, NotModelled, NoEffect };

struct CommandInfo {
  std::string_view name;
  Support support;
};
// Every command of the table, in table order (docs/language.md lists them).
std::span<const CommandInfo> all_commands();
// Every address with a value (one letter or extended: PW, CR, AP, RPL ...).
std::span<const std::string_view> all_addresses();

// Commands and procedures by upper-case name (ASPLINE, CYCLE832, TRAORI, CYCLE81 ...).
Support command_support(std::string_view upper_name);
// TRANSMIT, TRACYL, TRAANG, TRAORI, TRAFOOF: not modelled (warned), but handed to the
// interpreter all the same, which stops checking software limits while one is active.
bool is_transformation_command(std::string_view upper_name);
// G codes by number.
Support g_code_support(int64_t code);
// Addresses that carry a value: X Y Z A B C ... F S D H T, I1 J1 K1, PW SD PL CR AR AP RP TURN.
bool is_address(std::string_view upper_name);
// The one-letter addresses (most words of every program), inline: a jump, no call.
inline bool is_address_letter(char c) {
  switch (c) {
    case 'X': case 'Y': case 'Z': case 'A': case 'B': case 'C': case 'U': case 'V': case 'W': case 'I':
    case 'J': case 'K': case 'F': case 'S': case 'D': case 'H': case 'T': case 'E': case 'Q':
      return true;
    default:
      return false;
  }
}
// Extended addresses: an address letter with a numeric extension, X1= (axis), S1= (spindle),
// H7= (auxiliary function), D2=, T1=.
bool is_extended_address(std::string_view upper_name);
// The G code with internal number `index` (from 1) in G group `group` (PGA Fundamentals, list
// of G groups), for G[group]=index and $P_GG; -1 where drycut does not know the group.
int g_code_of_group(int group, int index);
// The named command with internal number `index` in a G group of named members (21 BRISK/SOFT/
// DRIVE, 30 COMPOF..COMPCAD, 59 DYNNORM..DYNPREC); empty if the group has none or no such index.
std::string_view named_code_of_group(int group, int index);
// The group and internal number of a G code, or false.
bool g_group_of_code(int code, int& group, int& index);
// The same for a G function written as text: "G17", "G500", or a named member ("SOFT", "COMPCAD").
bool g_group_of_name(std::string_view upper_name, int& group, int& index);
// Commands written with an axis index and no value (PGA Fundamentals, diameter programming
// and G96): DIAMONA[X], DIAMOFA[X], DIAM90A[X], DIACYCOFA[X], DIAMCHANA[X], SCC[X].
bool is_axis_indexed_command(std::string_view upper_name);
// Closest known command or keyword within a small edit distance ("ASPLIN" -> "ASPLINE"), or
// empty. Used to tell a misspelled word from an unknown subprogram.
std::string_view near_miss(std::string_view upper_name);

}  // namespace drycut::parser
