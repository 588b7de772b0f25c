#include "machine/alarm_catalog.hpp"

#include <algorithm>
#include <array>

namespace drycut {
namespace {

using S = Severity;
using A = AlarmSource;

// Sorted by number. Texts are paraphrased; numbers per docs/sinumerik-facts.md §5.
constexpr std::array kCatalog{
    AlarmInfo{10720, S::Alarm, "Software limit switch violated", A::Memory},
    AlarmInfo{10750, S::Alarm, "Tool radius compensation activated without tool number", A::Memory},
    AlarmInfo{10751, S::Alarm, "Danger of collision due to tool radius compensation", A::Memory},
    AlarmInfo{10753, S::Alarm, "Activation of tool radius compensation only possible in linear block", A::ThirdParty},
    AlarmInfo{10754, S::Alarm, "Deactivation of tool radius compensation only possible in linear block", A::ThirdParty},
    AlarmInfo{10757, S::Alarm, "Compensation plane changed while tool radius compensation is active", A::Siemens},
    AlarmInfo{10762, S::Alarm, "Too many empty blocks between two traversing blocks with tool radius compensation", A::Siemens},
    AlarmInfo{10763, S::Warning, "Path component of the block in the compensation plane becomes zero (block skipped by bottleneck detection)", A::Siemens},
    AlarmInfo{10860, S::Alarm, "Feedrate not programmed", A::ThirdParty},
    // Constant cutting rate (Function Manual V1 Feeds, "Constant cutting rate G96, G961": alarms).
    AlarmInfo{10900, S::Alarm, "No S value programmed for constant cutting rate", A::Siemens},
    AlarmInfo{10950, S::Alarm, "Arc-length function too inaccurate", A::Siemens},
    AlarmInfo{12000, S::Alarm, "Address programmed repeatedly", A::ThirdParty},
    AlarmInfo{12010, S::Alarm, "Address programmed too often in block", A::ThirdParty},
    AlarmInfo{12070, S::Alarm, "Too many syntax-defining G functions", A::ThirdParty},
    AlarmInfo{12080, S::Alarm, "Syntax error", A::ThirdParty},
    AlarmInfo{12150, S::Alarm, "Operation not compatible with data type", A::ThirdParty},
    AlarmInfo{12160, S::Alarm, "Value outside range", A::ThirdParty},
    AlarmInfo{12170, S::Alarm, "Name defined several times", A::ThirdParty},
    AlarmInfo{12340, S::Alarm, "Number of parameters too high", A::Memory},  // more call arguments than PROC parameters
    AlarmInfo{12410, S::Alarm, "Wrong index type", A::ThirdParty},
    AlarmInfo{12430, S::Alarm, "Index invalid", A::ThirdParty},
    AlarmInfo{12470, S::Alarm, "G function unknown", A::ThirdParty},
    AlarmInfo{12475, S::Alarm, "Invalid G function number", A::ThirdParty},
    AlarmInfo{12550, S::Alarm, "Name not defined or option not available", A::ThirdParty},
    AlarmInfo{12630, S::Alarm, "Skip identifier or label not allowed in control-structure block", A::ThirdParty},
    AlarmInfo{12640, S::Alarm, "Invalid nesting of control structures", A::ThirdParty},
    AlarmInfo{14011, S::Alarm, "Called program does not exist", A::Memory},
    AlarmInfo{14040, S::Alarm, "Error in end point of circle", A::Siemens},
    AlarmInfo{14048, S::Alarm, "Wrong number of revolutions in circle programming", A::ThirdParty},
    AlarmInfo{14051, S::Alarm, "Arithmetic error in part program", A::ThirdParty},
    AlarmInfo{14060, S::Alarm, "Invalid skip level with differential block skip", A::ThirdParty},
    AlarmInfo{14080, S::Alarm, "Jump destination not found", A::ThirdParty},
    AlarmInfo{14130, S::Alarm, "Too many initialization values", A::ThirdParty},
    AlarmInfo{14500, S::Alarm, "Illegal DEF or PROC instruction in part program", A::ThirdParty},
    AlarmInfo{14760, S::Alarm, "Auxiliary function of a group programmed repeatedly", A::Memory},
    AlarmInfo{14800, S::Alarm, "Programmed path velocity smaller than or equal to zero", A::ThirdParty},
    AlarmInfo{14820, S::Alarm, "Negative maximum spindle speed programmed for constant cutting rate", A::Siemens},
    // Contour preparation started wrongly (CONTPRON; drycut: DRYCUT_CONTOUR_BEGIN/END).
    AlarmInfo{15800, S::Alarm, "Wrong initial conditions for contour preparation (CONTPRON)", A::Memory},
    AlarmInfo{16420, S::Alarm, "Axis programmed repeatedly in block", A::ThirdParty},
    // Rotary axes (Diagnostics Manual; the texts as drycut understands them, docs/axes.md).
    AlarmInfo{16800, S::Alarm, "Traverse instruction DC/CDC not allowed for this axis", A::Memory},
    AlarmInfo{16810, S::Alarm, "Traverse instruction ACP not allowed for this axis", A::Memory},
    AlarmInfo{16820, S::Alarm, "Traverse instruction ACN not allowed for this axis", A::Memory},
    AlarmInfo{16830, S::Alarm, "Invalid modulo position programmed", A::Memory},
    AlarmInfo{17020, S::Alarm, "Illegal array index 1", A::Memory},
    AlarmInfo{17030, S::Alarm, "Illegal array index 2", A::Memory},
    AlarmInfo{17180, S::Alarm, "Illegal D number", A::Memory},
    AlarmInfo{17190, S::Alarm, "Illegal T number", A::Siemens},
    // drycut's own numbers: situations the control certainly rejects, but whose number no
    // public source gives.
    AlarmInfo{990001, S::Alarm, "Too few spline blocks in a window of 10 blocks", A::Drycut},
    AlarmInfo{990002, S::Warning, "Command not modelled by drycut; block executed without it", A::Drycut},
    AlarmInfo{990003, S::Alarm, "Program nesting deeper than 16 levels", A::Drycut},
    AlarmInfo{990004, S::Alarm, "Endless loop (the step limit is reached, or the program comes back to a state it had)", A::Drycut},
    AlarmInfo{990005, S::Alarm, "Program file cannot be read", A::Drycut},
    AlarmInfo{990006, S::Alarm, "Function not supported by drycut (it would change the path)", A::Drycut},
    AlarmInfo{990007, S::Warning, "Value not known to drycut; an assumed value is used (the detail names it)", A::Drycut},
    AlarmInfo{990010, S::Alarm, "Program contains no blocks", A::Drycut},
    AlarmInfo{990012, S::Warning, "Tool or cutting edge not in the tool table", A::Drycut},
    AlarmInfo{990013, S::Warning, "Programmed value limited by the machine data", A::Drycut},
    AlarmInfo{990014, S::Warning, "Program waits for an input or PLC signal; the wait is taken as ended at once", A::Drycut},
    AlarmInfo{990015, S::Warning, "Chamfer or rounding reduced: the blocks are too short for the programmed value", A::Drycut},
    AlarmInfo{990016, S::Warning, "Feed type changed (G93/G94/G95) without a new F: the previous value is read in the new unit", A::Drycut},
    AlarmInfo{990017, S::Warning, "Main program ends at the end of its file without M2, M30 or M17", A::Drycut},
    AlarmInfo{990018, S::Warning, "Name is a keyword of the control and a program in the search path: drycut calls the program", A::Drycut},
    AlarmInfo{990019, S::Warning, "G group 15 (feed type, spindle speed mode) changed what F or S mean", A::Drycut},
    AlarmInfo{990020, S::Alarm, "Path element without valid geometry (planner input)", A::Drycut},
    AlarmInfo{990021, S::Warning, "Cycle alarm not raised: it follows from an input, PLC signal or measured value a dry run does not know", A::Drycut},
    AlarmInfo{990022, S::Alarm, "Run interrupted (Ctrl-C or a termination signal): stopped before this block", A::Drycut},
};

}  // namespace

std::span<const AlarmInfo> alarm_catalog() { return kCatalog; }

const AlarmInfo* find_alarm(int number) {
  auto it = std::lower_bound(kCatalog.begin(), kCatalog.end(), number,
                             [](const AlarmInfo& a, int n) { return a.number < n; });
  return (it != kCatalog.end() && it->number == number) ? &*it : nullptr;
}

}  // namespace drycut
