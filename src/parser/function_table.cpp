#include "parser/function_table.hpp"

#include <array>

namespace drycut::parser {
namespace {

using F = Function;
// Sources: PGA Fundamentals "Arithmetic functions"; Job Planning "String operations",
// "Frames" (CTRANS ...), "Tool management" (GETT).
constexpr std::array kFunctions{
    FunctionInfo{"SIN", F::Sin, 1, 1, "sine, argument in degrees"},
    FunctionInfo{"COS", F::Cos, 1, 1, "cosine, argument in degrees"},
    FunctionInfo{"TAN", F::Tan, 1, 1, "tangent, argument in degrees"},
    FunctionInfo{"ASIN", F::Asin, 1, 1, "arc sine in degrees"},
    FunctionInfo{"ACOS", F::Acos, 1, 1, "arc cosine in degrees"},
    FunctionInfo{"ATAN2", F::Atan2, 2, 2, "ATAN2(y, x): angle of the vector (x, y) in degrees"},
    FunctionInfo{"SQRT", F::Sqrt, 1, 1, "square root"},
    FunctionInfo{"ABS", F::Abs, 1, 1, "absolute value"},
    FunctionInfo{"POT", F::Pot, 1, 2, "POT(x) = x squared, POT(x, y) = x to the power y"},
    FunctionInfo{"TRUNC", F::Trunc, 1, 1, "integer part (towards zero)"},
    FunctionInfo{"ROUND", F::Round, 1, 1, "rounds to the nearest integer, halves away from zero"},
    FunctionInfo{"ROUNDUP", F::RoundUp, 1, 1, "rounds up to the next integer (ceiling)"},
    FunctionInfo{"LN", F::Ln, 1, 1, "natural logarithm"},
    FunctionInfo{"EXP", F::Exp, 1, 1, "e to the power x"},
    FunctionInfo{"MINVAL", F::Min, 2, 2, "smaller of two values"},
    FunctionInfo{"MAXVAL", F::Max, 2, 2, "larger of two values"},
    FunctionInfo{"BOUND", F::Bound, 3, 3, "BOUND(min, max, x): x limited to [min, max]"},
    FunctionInfo{"QU", F::QuickOutput, 1, 1, "M=QU(8): quick output of an auxiliary function (its value)"},
    FunctionInfo{"ISAXIS", F::IsAxis, 1, 1, "TRUE when geometry axis 1..3 exists"},
    FunctionInfo{"STRLEN", F::StrLen, 1, 1, "length of a string"},
    FunctionInfo{"INDEX", F::Index, 2, 2, "first position (from 0) of a character in a string, -1 if none"},
    FunctionInfo{"RINDEX", F::RIndex, 2, 2, "last position of a character in a string, -1 if none"},
    FunctionInfo{"MINDEX", F::MIndex, 2, 2, "first position of any of the given characters, -1 if none"},
    FunctionInfo{"SUBSTR", F::SubStr, 2, 3, "SUBSTR(s, start[, count]): part of a string"},
    FunctionInfo{"TOUPPER", F::ToUpper, 1, 1, "string in upper case"},
    FunctionInfo{"TOLOWER", F::ToLower, 1, 1, "string in lower case"},
    FunctionInfo{"NUMBER", F::Number, 1, 1, "the number a string holds"},
    FunctionInfo{"ISNUMBER", F::IsNumber, 1, 1, "TRUE when a string holds a number"},
    FunctionInfo{"SPRINT", F::Sprint, 1, 20, "formatted string: %D %I %F %.nF %E %S %C %B %X"},
    FunctionInfo{"AXNAME", F::AxName, 1, 1, "the axis a string names"},
    FunctionInfo{"AXSTRING", F::AxString, 1, 1, "the name of an axis as a string"},
    FunctionInfo{"ISVAR", F::IsVar, 1, 1, "TRUE when the string names a known variable"},
    FunctionInfo{"ISFILE", F::IsFile, 1, 1, "TRUE when a program file of that name is in drycut's folders"},
    FunctionInfo{"STRINGIS", F::StringIs, 1, 1, "what the language knows a name as: 0, 2xx (201 address ... 211 LUD), 400"},
    FunctionInfo{"SPI", F::Spindle, 1, 1, "the axis of spindle n (SP<n>), for $AA_S[SPI(1)] and axis-indexed words"},
    FunctionInfo{"GETT", F::GetT, 1, 2, "GETT(name[, duplo]): T number of a named tool"},
    FunctionInfo{"CTRANS", F::FrameFunction, 0, 30, "frame with translations"},
    FunctionInfo{"CROT", F::FrameFunction, 0, 30, "frame with rotations"},
    FunctionInfo{"CSCALE", F::FrameFunction, 0, 30, "frame with scale factors"},
    FunctionInfo{"CMIRROR", F::FrameFunction, 0, 30, "frame with mirrored axes"},
    FunctionInfo{"CFINE", F::FrameFunction, 0, 30, "frame with fine translations"},
    FunctionInfo{"AC", F::AbsoluteMode, 1, 1, "absolute value of one address (X=AC(5))"},
    FunctionInfo{"IC", F::IncrementalMode, 1, 1, "incremental value of one address (X=IC(5))"},
    FunctionInfo{"DC", F::DirectMode, 1, 1, "rotary axis to an absolute position the shortest way"},
    FunctionInfo{"ACP", F::AbsolutePositive, 1, 1, "rotary axis to an absolute position in positive direction"},
    FunctionInfo{"ACN", F::AbsoluteNegative, 1, 1, "rotary axis to an absolute position in negative direction"},
    FunctionInfo{"SET", F::ArraySet, 1, 30, "NAME[i]=SET(a, b, ...): values for consecutive array elements from i"},
    FunctionInfo{"REP", F::ArrayRep, 1, 1, "NAME[i]=REP(v): v for element i and every element after it"},
};

}  // namespace

const FunctionInfo* find_function(std::string_view upper_name) {
  for (const auto& f : kFunctions)
    if (f.name == upper_name) return &f;
  return nullptr;
}

std::span<const FunctionInfo> all_functions() { return kFunctions; }

}  // namespace drycut::parser
