#include "parser/function_table.hpp"

#include <array>
#include <charconv>
#include <string>

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
    FunctionInfo{"ISVAR", F::IsVar, 1, 1, "TRUE when the string names a known variable (an index within the array)"},
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
    FunctionInfo{"DAC", F::DiameterAbsolute, 1, 1, "absolute diameter value of one axis word, whatever DIAMON/DIAMOF"},
    FunctionInfo{"DIC", F::DiameterIncremental, 1, 1, "incremental diameter value of one axis word"},
    FunctionInfo{"RAC", F::RadiusAbsolute, 1, 1, "absolute radius value of one axis word, whatever DIAMON/DIAMOF"},
    FunctionInfo{"RIC", F::RadiusIncremental, 1, 1, "incremental radius value of one axis word"},
    FunctionInfo{"PM", F::PerMinute, 1, 1, "FAD=PM(f): the smooth approach's infeed feed per minute, whatever G94/G95"},
    FunctionInfo{"PR", F::PerRevolution, 1, 1, "FAD=PR(f): the smooth approach's infeed feed per revolution, whatever G94/G95"},
    FunctionInfo{"CALCDAT", F::CircleData, 3, 3, "CALCDAT(points[n,2], 3 or 4, result[3]): circle centre and radius (4 points: mean of the centres of the triples, drycut's choice); FALSE when none"},
    FunctionInfo{"MATCH", F::Match, 2, 2, "first position (from 0) of a string in a string, -1 if none"},
    FunctionInfo{"ITOR", F::ToReal, 1, 1, "INT to REAL"},
    FunctionInfo{"BTOR", F::ToReal, 1, 1, "BOOL to REAL"},
    FunctionInfo{"RTOI", F::ToInt, 1, 1, "REAL to INT, rounded (halves away from zero)"},
    FunctionInfo{"BTOI", F::ToInt, 1, 1, "BOOL to INT"},
    FunctionInfo{"ITOB", F::ToBool, 1, 1, "INT to BOOL (not zero)"},
    FunctionInfo{"RTOB", F::ToBool, 1, 1, "REAL to BOOL (not zero)"},
    FunctionInfo{"NAMETOINT", F::NameToInt, 2, 3,
                 "NAMETOINT(\"$MC_AXCONF_CHANAX_NAME_TAB\", \"X\"[, no alarm]): index of a name in a system array (from 0, inferred)"},
    // Valid predefined functions drycut does not compute (Job Planning and NC Programming,
    // "Predefined functions"; Function Manual Tool Management; K2 frames): warning 990002 and
    // the result of a call that went well; "#n" is the value of argument n. VAR results stay.
    FunctionInfo{"GETDNO", F::Assumed, 2, 2, "D number of cutting edge CE of tool T", "#2"},
    FunctionInfo{"SETDNO", F::Assumed, 3, 3, "gives cutting edge CE of tool T the D number D", "TRUE"},
    FunctionInfo{"CHKDNO", F::Assumed, 0, 3, "TRUE when the D numbers are unique", "TRUE"},
    FunctionInfo{"CHKDM", F::Assumed, 1, 3, "checks D numbers unique in a magazine: 0", "0"},
    FunctionInfo{"GETACTT", F::Assumed, 2, 2, "active tool of a tool group into VAR T: status", "0"},
    FunctionInfo{"GETACTTD", F::Assumed, 2, 2, "tool of an absolute D number into VAR T: status", "0"},
    FunctionInfo{"NEWT", F::Assumed, 1, 2, "creates a tool: its T number", "1"},
    FunctionInfo{"DELDL", F::Assumed, 1, 2, "deletes additive offsets: status", "0"},
    FunctionInfo{"DELMLRES", F::Assumed, 2, 3, "deletes a location reservation: status", "0"},
    FunctionInfo{"DELMLOWNER", F::Assumed, 1, 1, "deletes a tool's owner location: status", "0"},
    FunctionInfo{"NEWMT", F::Assumed, 2, 3, "creates a multitool: its number", "1"},
    FunctionInfo{"TOOLENV", F::Assumed, 1, 1, "saves the tool environment: status", "0"},
    FunctionInfo{"DELTOOLENV", F::Assumed, 0, 1, "deletes tool environments: status", "0"},
    FunctionInfo{"GETTENV", F::Assumed, 2, 2, "reads a tool environment into VAR: status", "0"},
    FunctionInfo{"GETTCOR", F::Assumed, 2, 7, "tool lengths into VAR: status", "0"},
    FunctionInfo{"SETTCOR", F::Assumed, 2, 10, "changes tool components: status", "0"},
    FunctionInfo{"TOOLGNT", F::Assumed, 1, 1, "number of tools in a tool group", "1"},
    FunctionInfo{"TOOLGT", F::Assumed, 2, 2, "T number of the n-th tool of a group", "1"},
    FunctionInfo{"GETVARTYP", F::Assumed, 1, 1, "data type code of a variable (4 = REAL)", "4"},
    FunctionInfo{"GETVARPHU", F::Assumed, 1, 1, "physical unit code of a variable", "0"},
    FunctionInfo{"GETVARAP", F::Assumed, 2, 2, "protection level of a variable", "7"},
    FunctionInfo{"GETVARLIM", F::Assumed, 3, 3, "limit of a variable into VAR: status", "0"},
    FunctionInfo{"GETVARDFT", F::Assumed, 2, 5, "default value of a variable into VAR: status", "0"},
    FunctionInfo{"AXTOSPI", F::Assumed, 1, 1, "spindle number of an axis", "1"},
    FunctionInfo{"MODAXVAL", F::Assumed, 2, 2, "modulo position of a rotary axis (the position)", "#2"},
    FunctionInfo{"POSRANGE", F::Assumed, 3, 4, "TRUE when the axis is inside the window", "TRUE"},
    FunctionInfo{"LENTOAX", F::Assumed, 3, 3, "tool lengths per geometry axis into VAR: status", "0"},
    FunctionInfo{"CALCPOSI", F::Assumed, 4, 6, "distance to the software limits into VAR: status", "0"},
    FunctionInfo{"INTERSEC", F::Assumed, 3, 4, "intersection of two contour elements into VAR", "TRUE"},
    FunctionInfo{"CHECKSUM", F::Assumed, 2, 4, "checksum of an array into VAR: status", "0"},
    FunctionInfo{"PROTD", F::Assumed, 2, 10, "distance of two protection areas", "0"},
    FunctionInfo{"COLLPAIR", F::Assumed, 2, 3, "state of a collision pair", "0"},
    FunctionInfo{"MEASURE", F::Assumed, 0, 30, "measuring calculation: status", "0"},
    FunctionInfo{"ADDFRAME", F::Assumed, 2, 2, "chains a frame into a system frame: status", "0"},
    FunctionInfo{"INVFRAME", F::Assumed, 1, 1, "inverse of a frame", "FRAME"},
    FunctionInfo{"CRPL", F::Assumed, 2, 2, "rotation frame in a plane", "FRAME"},
    FunctionInfo{"CROTS", F::Assumed, 2, 6, "rotation frame from solid angles", "FRAME"},
    FunctionInfo{"MEAFRAME", F::Assumed, 3, 3, "frame from three measured points", "FRAME"},
    // Curve tables (Function Manual Extended Functions M3, "Curve tables"): not modelled.
    FunctionInfo{"CTAB", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABINV", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABEXISTS", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABFNO", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABFPOL", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABFSEG", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABID", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABISLOCK", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABMEMTYP", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABMPOL", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABMSEG", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABNO", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABNOMEM", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABPERIOD", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABPOL", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABPOLID", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABSEG", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABSEGID", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABSEV", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABSSV", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABTEP", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABTEV", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABTMAX", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABTMIN", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABTSP", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"CTABTSV", F::Assumed, 0, 6, "curve table function", "0"},
    FunctionInfo{"SET", F::ArraySet, 1, 30, "NAME[i]=SET(a, b, ...): values for consecutive array elements from i"},
    FunctionInfo{"REP", F::ArrayRep, 1, 1, "NAME[i]=REP(v): v for element i and every element after it"},
};

}  // namespace

Value assumed_result(const FunctionInfo& f) {
  const std::string_view a = f.assumed;
  if (a == "FRAME") {  // the null frame, in the text the interpreter computes frames from
    Value v = Value::of_frame();
    v.text = "CTRANS()";
    return v;
  }
  if (a == "TRUE") return Value(1.0);
  if (a == "FALSE") return Value(0.0);
  if (a.size() >= 2 && a.front() == '"') return Value::of_text(std::string(a.substr(1, a.size() - 2)));
  double v = 0.0;
  std::from_chars(a.data(), a.data() + a.size(), v);
  return Value(v);
}

const FunctionInfo* find_function(std::string_view upper_name) {
  for (const auto& f : kFunctions)
    if (f.name == upper_name) return &f;
  return nullptr;
}

std::span<const FunctionInfo> all_functions() { return kFunctions; }

}  // namespace drycut::parser
