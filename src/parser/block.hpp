#pragma once
// The block stream's unit: one executed NC block with every expression already evaluated.
// The ProgramLoader produces these after following calls, jumps and control structures; the
// interpreter gives them meaning. Syntax only: nothing here knows what G1 does.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "parser/value.hpp"
#include "machine/source_location.hpp"

namespace drycut::parser {

// How an address value was written: plain `X5`, `X=AC(5)` / `X=IC(5)`, or for a rotary axis
// `C=DC(5)` (the shortest way), `C=ACP(5)` / `C=ACN(5)` (absolute, positive / negative way).
// How an address value was written: as it stands (G90/G91 decide), AC/IC, the rotary ways
// DC/ACP/ACN, or the blockwise diameter/radius values DAC/DIC/RAC/RIC (Fundamentals, "Diameter/
// radius programming for a specific axis"): a diameter or a radius whatever DIAMON/DIAMOF says.
enum class ValueMode : uint8_t {
  Default, Absolute, Incremental, Direct, AbsolutePositive, AbsoluteNegative,
  DiameterAbsolute /*DAC*/, DiameterIncremental /*DIC*/, RadiusAbsolute /*RAC*/, RadiusIncremental /*RIC*/,
  PerMinute /*PM: FAD only*/, PerRevolution /*PR: FAD only*/
};
// AC and IC, or a blockwise diameter/radius value: the modes a linear axis accepts.
constexpr bool is_linear_value_mode(ValueMode m) {
  return m != ValueMode::Direct && m != ValueMode::AbsolutePositive && m != ValueMode::AbsoluteNegative;
}
constexpr bool is_incremental_mode(ValueMode m) {
  return m == ValueMode::Incremental || m == ValueMode::DiameterIncremental || m == ValueMode::RadiusIncremental;
}
constexpr bool is_absolute_mode(ValueMode m) {
  return m == ValueMode::Absolute || m == ValueMode::DiameterAbsolute || m == ValueMode::RadiusAbsolute;
}

// An address with a numeric value: axis words X Y Z A B C, circle I J K I1 J1 K1, F S D H,
// T<n>, and the extended addresses PW SD PL CR AR TURN AP RP ... Name is upper case.
struct AddressWord {
  std::string name;
  double value = 0.0;
  ValueMode mode = ValueMode::Default;
  uint32_t column = 0;
};

struct GWord {
  int code = 0;  // G1 -> 1, G642 -> 642
  uint32_t column = 0;
};

struct MWord {
  int code = 0;        // M3 -> 3
  int extension = -1;  // M1=3 -> extension 1 (spindle number); -1 = none
  uint32_t column = 0;
};

// A procedure argument: a number, a string, or a bare name (axis names in SPLINEPATH).
using Argument = std::variant<double, std::string>;

// A named command or procedure call: ASPLINE, SOFT, BTAN, G642 is a GWord not a command,
// CYCLE832(0.01,1), MSG("text"), SPLINEPATH(1,X,Y,Z), TRANS (its axis words are addresses).
struct CommandWord {
  std::string name;  // upper case
  std::vector<Argument> args;
  bool has_parentheses = false;
  uint32_t column = 0;
};

// A `$` system variable written in the block ($TC_DP6[1,1]=4, $P_UIFR[1]=...,
// $MA_COMPRESS_POS_TOL[X1]=0.01): the interpreter applies those it models.
struct SystemWrite {
  std::string name;  // upper case, with '$'
  std::vector<Value> indices;
  Value value;
  uint32_t column = 0;
};

// Positioning-axis words (PGA Fundamentals "Traversing positioning axes"; Spindle SPOS):
// POS[ax]= and POSA[ax]= move an axis on its own interpolator, SPOS=/SPOSA= position the
// spindle, FA[ax]= sets a positioning axis's feed. ACC[ax]=, VELOLIM[ax]=, JERKLIM[ax]= scale an
// axis's acceleration, velocity and jerk limits in percent (Fundamentals, "Programmable
// acceleration override (ACC)"; Function Manual B2, "Programmable dynamic limits").
enum class AxisWordKind : uint8_t { Pos, PosA, SPos, SPosA, AxialFeed, AccelPercent, VelocityPercent, JerkPercent, FeedReferenceRadius };
struct AxisWord {
  AxisWordKind kind = AxisWordKind::Pos;
  std::string axis;  // upper case; the spindle number as text for SPOS[n] (empty for SPOS=: the master)
  double value = 0.0;
  ValueMode mode = ValueMode::Default;
  uint32_t column = 0;
};

// POLY: PO[ax]=(end, a2, a3, a4, a5) gives an axis's polynomial (its end point also stands in
// the block as the axis word ax=end); PO[]=(b2, b3, b4), axis empty, the common denominator
// (PGA Fundamentals, "Polynomial interpolation (POLY, POLYPATH, PO, PL)").
struct PolyWord {
  std::string axis;  // upper case; empty for PO[]
  std::vector<double> values;
  uint32_t column = 0;
};

// PROC ... SAVE: the subprogram's first block asks the interpreter to keep its modal state,
// the block after the return to restore it (PGA Job Planning, "SAVE").
enum class ModalSave : uint8_t { None, Save, Restore };

struct Block {
  FileName file = nullptr;  // interned: the same pointer for all blocks of one file
  uint32_t line = 0;
  std::string text;                // the block as written, trimmed, decoded to UTF-8
  std::optional<int64_t> number;   // N123 or :123
  int program_level = 0;           // 0 = main program, 1.. = subprogram nesting depth
  // The block or a line before it (since the last block) read a main-run variable ($AA_IW,
  // $A_IN ...): an implicit preprocessing stop before the block (Job Planning, STOPRE).
  bool main_run_read = false;
  std::vector<GWord> g;
  std::vector<MWord> m;
  std::vector<AddressWord> addresses;
  std::vector<CommandWord> commands;
  std::optional<std::string> tool_name;  // T="name" (case preserved)
  int tool_name_spindle = 0;             // T<n>="name": spindle n (0: T= without extension)
  std::vector<SystemWrite> system_writes;
  std::vector<AxisWord> axis_words;
  std::vector<PolyWord> poly;
  ModalSave modal_save = ModalSave::None;

  // Empties the block but keeps the vectors' capacity (the loader reuses one Block).
  void clear() {
    file = nullptr;
    line = 0;
    text.clear();
    number.reset();
    program_level = 0;
    main_run_read = false;
    g.clear();
    m.clear();
    addresses.clear();
    commands.clear();
    tool_name.reset();
    tool_name_spindle = 0;
    system_writes.clear();
    axis_words.clear();
    poly.clear();
    modal_save = ModalSave::None;
  }

  const AddressWord* find_address(std::string_view name) const {
    for (const auto& a : addresses)
      if (std::string_view(a.name) == name) return &a;
    return nullptr;
  }
  bool has_g(int code) const {
    for (const auto& w : g)
      if (w.code == code) return true;
    return false;
  }
  bool has_m(int code) const {
    for (const auto& w : m)
      if (w.code == code) return true;
    return false;
  }
  const CommandWord* find_command(std::string_view name) const {
    for (const auto& c : commands)
      if (c.name == name) return &c;
    return nullptr;
  }
};

}  // namespace drycut::parser
