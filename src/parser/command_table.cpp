#include "parser/command_table.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace drycut::parser {
namespace {

using CommandEntry = CommandInfo;

constexpr Support M = Support::Modelled;
constexpr Support N = Support::NotModelled;
constexpr Support E = Support::NoEffect;

// Commands the interpreter gives meaning to, then valid ones it does not model (yet).
constexpr std::array kCommands{
    CommandEntry{"ASPLINE", M}, CommandEntry{"BSPLINE", M}, CommandEntry{"CSPLINE", M},
    CommandEntry{"CIP", M},     CommandEntry{"CT", M},      CommandEntry{"BAUTO", M},
    CommandEntry{"BNAT", M},    CommandEntry{"BTAN", M},    CommandEntry{"EAUTO", M},
    CommandEntry{"ENAT", M},    CommandEntry{"ETAN", M},    CommandEntry{"SOFT", M},
    CommandEntry{"BRISK", M},   CommandEntry{"NORM", M},    CommandEntry{"KONT", M},
    CommandEntry{"CDON", M},    CommandEntry{"CDOF", M},    CommandEntry{"TRANS", M},
    CommandEntry{"ATRANS", M},  CommandEntry{"SPLINEPATH", M},
    CommandEntry{"MSG", M},     CommandEntry{"RET", M},
    CommandEntry{"POLY", M},    CommandEntry{"POLYPATH", N},  // which axis groups POLY bends: not modelled
    CommandEntry{"COMPON", M},  CommandEntry{"COMPCURV", M}, CommandEntry{"COMPCAD", M},
    CommandEntry{"COMPOF", M},  CommandEntry{"COMPSURF", M},  // planned as COMPCAD, warned
    // drycut's own, for its contour cycles (interp/contour_recording.hpp; the control's cycles
    // use CONTPRON/EXECUTE): record the contour of the blocks between, run a contour by name.
    CommandEntry{"DRYCUT_CONTOUR_BEGIN", M}, CommandEntry{"DRYCUT_CONTOUR_END", M},
    CommandEntry{"DRYCUT_CONTOUR_CALL", M},
    // Valid on the control, not modelled by drycut.
    CommandEntry{"TRAORI", N},  CommandEntry{"TRACYL", N},
    // TRAFOOF ends a transformation: drycut models none (each is warned where it is selected),
    // but checks the software limits of X/Y/Z again (docs/axes.md). FFWON/FFWOF change the
    // following error of the position loop, not the set-point path and its time that drycut
    // plans (docs/controller-state.md).
    CommandEntry{"TRAFOOF", M}, CommandEntry{"FFWON", E},   CommandEntry{"FFWOF", E},
    CommandEntry{"TRANSMIT", N},   CommandEntry{"ROT", M},     CommandEntry{"AROT", M},
    CommandEntry{"SCALE", M},   CommandEntry{"ASCALE", M},  CommandEntry{"MIRROR", M},
    CommandEntry{"AMIRROR", M}, CommandEntry{"UPATH", N},   CommandEntry{"SPATH", E},
    CommandEntry{"CFC", M},     CommandEntry{"CFTCP", M},   CommandEntry{"CFIN", M},
    CommandEntry{"DRIVE", N},   CommandEntry{"DYNNORM", M}, CommandEntry{"DYNPOS", M},
    CommandEntry{"DYNROUGH", M}, CommandEntry{"DYNSEMIFIN", M}, CommandEntry{"DYNFINISH", M},
    CommandEntry{"ORIWKS", N},  CommandEntry{"ORIMKS", N},  CommandEntry{"ORIAXES", N},
    CommandEntry{"ORIVECT", N}, CommandEntry{"CUT2D", E},   CommandEntry{"CUT3DC", N},
    CommandEntry{"SUPA", M},    CommandEntry{"DIAMON", M},  CommandEntry{"DIAMOF", M},
    CommandEntry{"SPOS", M},    CommandEntry{"SETMS", M},   CommandEntry{"WAITM", N},
    CommandEntry{"FGROUP", M},  CommandEntry{"FNORM", E},   CommandEntry{"FLIN", N},
    CommandEntry{"FCUB", N},    CommandEntry{"TCARR", N},   CommandEntry{"TCOABS", M},
    CommandEntry{"TCOFR", M},   CommandEntry{"CPRECON", N}, CommandEntry{"CPRECOF", N},
    CommandEntry{"SOFTA", N},   CommandEntry{"BRISKA", N},  
    CommandEntry{"WORKPIECE", E}, CommandEntry{"MCALL", M},
    CommandEntry{"EXTCALL", M}, CommandEntry{"PCALL", M},
    CommandEntry{"POS", M},     CommandEntry{"POSA", M},    CommandEntry{"SPOSA", M},
    CommandEntry{"WAITP", M},   CommandEntry{"WAITS", M},
    CommandEntry{"PRESETON", N}, CommandEntry{"CPROT", N},  CommandEntry{"ORIRESET", N},
    CommandEntry{"FL", N},      CommandEntry{"ACC", M},     CommandEntry{"JERKLIM", M},
    CommandEntry{"VELOLIM", M}, CommandEntry{"FGREF", M},
    // OTOL: the orientation tolerance of smoothing/compressors, which only acts under an
    // orientation transformation (TRAORI), itself not modelled and warned.
    CommandEntry{"OTOL", E},    CommandEntry{"TOFFON", N},
    CommandEntry{"TOFFOF", N},  CommandEntry{"TOFFL", N},   CommandEntry{"TOFF", N},
    CommandEntry{"CUTMOD", N},  CommandEntry{"ORISON", N},  CommandEntry{"ORISOF", N},
    CommandEntry{"MEAS", N},    CommandEntry{"MEASW", N},   CommandEntry{"DIAM90", M},
    CommandEntry{"TRAILON", N}, CommandEntry{"TRAILOF", N}, CommandEntry{"COUPON", N},
    CommandEntry{"COUPOF", N},  CommandEntry{"SPCON", N},   CommandEntry{"SPCOF", N},
    // Corner deceleration, 3-D compensation, orientation and transformation modes, buffer control:
    // valid on a 5-axis control, their effect on the path is not modelled.
    CommandEntry{"FENDNORM", N}, CommandEntry{"CUT2DF", N}, CommandEntry{"CUT3DF", N},
    CommandEntry{"CUT3DFF", N}, CommandEntry{"CUT3DFS", N}, CommandEntry{"ORIEULER", N},
    CommandEntry{"ORIRPY", N}, CommandEntry{"ORIRPY2", N}, CommandEntry{"ORIPLANE", N},
    CommandEntry{"ORIC", N}, CommandEntry{"ORID", N}, CommandEntry{"OSOF", N},
    CommandEntry{"OSC", N}, CommandEntry{"OSS", N}, CommandEntry{"OSSE", N}, CommandEntry{"OSD", N},
    CommandEntry{"OST", N}, CommandEntry{"PTP", N},
    // ORIS= orientation smoothing factor; STAT= / TU= the joint position and turn of a
    // Cartesian PTP move under TRAORI; STOLF= the G0 tolerance factor (MD20560), CTOLG0= /
    // OTOLG0= the absolute G0 tolerances (Job Planning, "Tool orientation", "Cartesian PTP
    // travel", "Tolerance for G0 motion"): valid, not modelled, warned.
    CommandEntry{"ORIS", N}, CommandEntry{"STAT", N}, CommandEntry{"TU", N}, CommandEntry{"STOLF", N},
    CommandEntry{"CTOLG0", N}, CommandEntry{"OTOLG0", N},
    CommandEntry{"CP", N}, CommandEntry{"PTPG0", N}, CommandEntry{"TRAANG", N},
    CommandEntry{"TRACON", N}, CommandEntry{"FIFOCTRL", E}, CommandEntry{"DRIVEA", N},
    CommandEntry{"ORICONCW", N}, CommandEntry{"ORICONCCW", N}, CommandEntry{"ORICONIO", N},
    CommandEntry{"ORICONTO", N}, CommandEntry{"ORICURVE", N}, CommandEntry{"ORIROTA", N}, CommandEntry{"ORIROTR", N},
    CommandEntry{"ORIROTT", N},  CommandEntry{"ORIROTC", N},
    // Orientation words of 5/6-axis programs: cone opening angle (ORICONxx), the second contact
    // point of ORICURVE, the tool's rotation angle, CUT3DC's insertion depth.
    CommandEntry{"NUT", N},      CommandEntry{"XH", N},       CommandEntry{"YH", N},
    CommandEntry{"ZH", N},       CommandEntry{"THETA", N},    CommandEntry{"ISD", N}, CommandEntry{"MEASA", N},
    CommandEntry{"MEAWA", N},   CommandEntry{"OVRA", N},    CommandEntry{"OVRRAP", N},
    CommandEntry{"WAITMC", N}, CommandEntry{"WAITE", N},
    CommandEntry{"ORIVIRT1", N}, CommandEntry{"ORIVIRT2", N}, CommandEntry{"ORIAXPOS", N},
    CommandEntry{"ORIPATH", N}, CommandEntry{"ORIPATHS", N}, CommandEntry{"STOPREOF", N},
    CommandEntry{"FA", M},      CommandEntry{"DYNPREC", M},
    // Contour definition by an angle (Fundamentals, "Contour definitions"): ANG is an address
    // (kAddresses below), as are the corner words RND, RNDM, CHF, CHR, FRC, FRCM.
    // Smooth approach and retraction parameters, tool offsets along the
    // path, lead/tilt angles, continuous measurement (Fundamentals, Job Planning).
    CommandEntry{"DISRP", N},
    CommandEntry{"TOFFR", N},   CommandEntry{"LEAD", N},
    CommandEntry{"TILT", N},    CommandEntry{"MEAW", N},    CommandEntry{"MEAC", N},
    CommandEntry{"RTLION", N},  CommandEntry{"RTLIOF", N},
    // Frame commands that align the frame with the tool or rotate by solid angles (Job
    // Planning, "Frames"): the frame they build is not computed.
    CommandEntry{"TOFRAME", N}, CommandEntry{"TOFRAMEX", N}, CommandEntry{"TOFRAMEY", N},
    CommandEntry{"TOFRAMEZ", N}, CommandEntry{"TOROT", N},  CommandEntry{"TOROTX", N},
    CommandEntry{"TOROTY", N},  CommandEntry{"TOROTZ", N},  CommandEntry{"TOROTOF", N},
    CommandEntry{"PAROT", N},   CommandEntry{"PAROTOF", N}, CommandEntry{"ROTS", N},
    CommandEntry{"AROTS", N},   CommandEntry{"CROTS", N},
    // Predefined procedures of tool management, synchronized actions, files and axis dynamics
    // (Job Planning; Function Manual Tool Management): valid calls, no path of their own.
    CommandEntry{"SETPIECE", N}, CommandEntry{"GETACTT", N}, CommandEntry{"NEWT", N},
    CommandEntry{"DELT", N},    CommandEntry{"GETSELT", M}, CommandEntry{"GETEXET", M},
    CommandEntry{"TCA", M},     CommandEntry{"POSM", N},    CommandEntry{"RESETMON", N},
    CommandEntry{"SETMTH", N},  CommandEntry{"CANCEL", N},  CommandEntry{"LOCK", N},
    CommandEntry{"UNLOCK", N},  CommandEntry{"RESET", N},   CommandEntry{"NEWCONF", N},
    CommandEntry{"WRITE", N},   CommandEntry{"READ", N},    CommandEntry{"DELETE", N},
    CommandEntry{"JERKA", N},
    // Turning: thread run-in/run-out and fast retraction (DITS=, DITE=, LFON, DILF=, ALF=),
    // spindle coupling for part transfer (COUPDEF ...), diameter switching of cycles
    // (Fundamentals and Job Planning, turning sections): not modelled, warned by name.
    CommandEntry{"DITS", N},    CommandEntry{"DITE", N},    CommandEntry{"DILF", N},
    CommandEntry{"ALF", N},     CommandEntry{"LFON", N},    CommandEntry{"LFOF", N},
    CommandEntry{"LFPOS", N},   CommandEntry{"LFWP", N},    CommandEntry{"LFTXT", N},
    CommandEntry{"COUPDEF", N}, CommandEntry{"COUPONC", N}, CommandEntry{"COUPOFS", N},
    CommandEntry{"COUPDEL", N}, CommandEntry{"COUPRES", N}, CommandEntry{"WAITC", N},
    CommandEntry{"DIAMCHAN", M}, CommandEntry{"DIAMCYCOF", M},
    // Axis-specific diameter programming and the reference axis of G96 (Fundamentals,
    // "Dimensions for turning" and "Constant cutting rate"): written NAME[axis].
    CommandEntry{"DIAMONA", M}, CommandEntry{"DIAMOFA", M}, CommandEntry{"DIAM90A", M},
    CommandEntry{"DIACYCOFA", M}, CommandEntry{"DIAMCHANA", M}, CommandEntry{"SCC", M},
    // Travel to fixed stop (Fundamentals, "Travel to fixed stop"): FXS[ax]=1/0, torque FXST[ax]=,
    // monitoring window FXSW[ax]=. The axis stops at the stop, not at the end point: warned.
    CommandEntry{"FXS", N},     CommandEntry{"FXST", N},    CommandEntry{"FXSW", N},
    // Axis words written NAME[axis]=value (Job Planning): the fast retraction position POLF,
    // oscillation (OS, OSP1/OSP2 reversal points, OST1/OST2 stop times, OSE end position,
    // OSNSC spark-out strokes, OSCTRL options, OSB), leading-axis coupling limits
    // (VELOLIMA/ACCLIMA/JERKLIMA), handwheel override FDA, axial feed of sync actions FMA,
    // positioning in parts POSP, travel with limited torque FOCON/FOCOF. Valid, not modelled: warned.
    CommandEntry{"POLF", N},    CommandEntry{"OS", N},      CommandEntry{"OSP1", N},
    CommandEntry{"OSP2", N},    CommandEntry{"OST1", N},    CommandEntry{"OST2", N},
    CommandEntry{"OSE", N},     CommandEntry{"OSNSC", N},   CommandEntry{"OSCTRL", N},
    CommandEntry{"OSB", N},     CommandEntry{"VELOLIMA", N}, CommandEntry{"ACCLIMA", N},
    CommandEntry{"JERKLIMA", N}, CommandEntry{"FDA", N},    CommandEntry{"FMA", N},
    CommandEntry{"POSP", N},    CommandEntry{"FOCON", N},   CommandEntry{"FOCOF", N},
    // The remaining predefined procedures of the control (NC Programming / Job Planning, lists
    // "Predefined procedures"): files, curve tables, couplings, tool management, channel
    // coordination, protection areas, tangential control. Valid calls, not modelled: warned.
    CommandEntry{"ADISPOSA", N}, CommandEntry{"AUXFUDEL", N}, CommandEntry{"AUXFUDELG", N},
    CommandEntry{"AUXFUMSEQ", N}, CommandEntry{"AUXFUSYNC", N}, CommandEntry{"AXCTSWE", N},
    CommandEntry{"AXCTSWEC", N}, CommandEntry{"AXCTSWED", N}, CommandEntry{"AXTOCHAN", N},
    CommandEntry{"CALLPATH", N}, CommandEntry{"CANCELSUB", N}, CommandEntry{"CHANDATA", N},
    CommandEntry{"CONTDCON", N}, CommandEntry{"CONTPRON", N}, CommandEntry{"CORROF", N},
    CommandEntry{"CPROTDEF", N}, CommandEntry{"CTABDEF", N}, CommandEntry{"CTABDEL", N},
    CommandEntry{"CTABLOCK", N}, CommandEntry{"CTABUNLOCK", N}, CommandEntry{"DELAYFSTOF", N},
    CommandEntry{"DELAYFSTON", N}, CommandEntry{"DELDTG", N}, CommandEntry{"DELMT", N},
    CommandEntry{"DELTC", N}, CommandEntry{"DZERO", N}, CommandEntry{"EGDEF", N},
    CommandEntry{"EGDEL", N}, CommandEntry{"EGOFC", N}, CommandEntry{"EGOFS", N},
    CommandEntry{"EGON", N}, CommandEntry{"EGONSYN", N}, CommandEntry{"EGONSYNE", N},
    CommandEntry{"ESRR", N}, CommandEntry{"ESRS", N}, CommandEntry{"EXECSTRING", M},
    CommandEntry{"EXECTAB", N}, CommandEntry{"EXECUTE", N}, CommandEntry{"EXTCLOSE", N},
    CommandEntry{"EXTOPEN", N}, CommandEntry{"FCTDEF", N}, CommandEntry{"FILEDATE", N},
    CommandEntry{"FILEINFO", N}, CommandEntry{"FILESIZE", N}, CommandEntry{"FILESTAT", N},
    CommandEntry{"FILETIME", N}, CommandEntry{"FPO", N}, CommandEntry{"FPR", N},
    CommandEntry{"FPRAOF", N}, CommandEntry{"FPRAON", N}, CommandEntry{"FTOC", N},
    CommandEntry{"GEOAX", N}, CommandEntry{"GET", N}, CommandEntry{"GETD", N},
    CommandEntry{"GETFREELOC", N}, CommandEntry{"GWPSOF", N}, CommandEntry{"GWPSON", N},
    CommandEntry{"ICYCOF", N}, CommandEntry{"ICYCON", N}, CommandEntry{"INIT", N},
    CommandEntry{"IPOBRKA", N}, CommandEntry{"LEADOF", N}, CommandEntry{"LEADON", N},
    CommandEntry{"MASLDEF", N}, CommandEntry{"MASLDEL", N}, CommandEntry{"MASLOF", N},
    CommandEntry{"MASLOFS", N}, CommandEntry{"MASLON", N}, CommandEntry{"MMC", N},
    CommandEntry{"MVTOOL", N}, CommandEntry{"NPROT", N}, CommandEntry{"NPROTDEF", N},
    CommandEntry{"POLFA", N}, CommandEntry{"POLFMASK", N}, CommandEntry{"POLFMLIN", N},
    CommandEntry{"POSMT", N}, CommandEntry{"PRESETONS", N}, CommandEntry{"PROTA", N},
    CommandEntry{"PROTS", N}, CommandEntry{"PUNCHACC", N}, CommandEntry{"PUTFTOC", N},
    CommandEntry{"PUTFTOCF", N}, CommandEntry{"RDISABLE", N}, CommandEntry{"RELEASE", N},
    CommandEntry{"SETTA", N}, CommandEntry{"SETTIA", N}, CommandEntry{"SIRELIN", N},
    CommandEntry{"SIRELOUT", N}, CommandEntry{"SIRELTIME", N}, CommandEntry{"START", N},
    CommandEntry{"SYNFCT", N}, CommandEntry{"TANG", N}, CommandEntry{"TANGDEL", N},
    CommandEntry{"TANGOF", N}, CommandEntry{"TANGON", N}, CommandEntry{"TCI", N},
    CommandEntry{"TLIFT", N}, CommandEntry{"TML", N}, CommandEntry{"TMOF", N},
    CommandEntry{"TMON", N}, CommandEntry{"TRAFOON", N}, CommandEntry{"WAITENC", N},
    // Working-area limitation on/off: drycut does not monitor the working area (G25/G26 with
    // axis words are warned too), so switching the monitoring is warned by name.
    CommandEntry{"WALIMON", N}, CommandEntry{"WALIMOF", N},
    // Valid, and modelled by doing nothing: they change display, single-block or buffer
    // behaviour, nothing a dry run measures.
    CommandEntry{"SBLOF", E},   CommandEntry{"SBLON", E},   CommandEntry{"DISPLOF", E},
    CommandEntry{"DISPLON", E}, CommandEntry{"SAVE", E},    CommandEntry{"ACTBLOCNO", E},
    CommandEntry{"DRFOF", E},   CommandEntry{"STARTFIFO", E}, CommandEntry{"STOPFIFO", E},
    CommandEntry{"STOPRE", M},  CommandEntry{"IPTRLOCK", E}, CommandEntry{"IPTRUNLOCK", E},
    CommandEntry{"CLEARM", E},  CommandEntry{"SETM", E},    CommandEntry{"WRTPR", E},
    CommandEntry{"RMI", E},     CommandEntry{"RMB", E},     CommandEntry{"RME", E},
    CommandEntry{"RMN", E},
    CommandEntry{"RMBBL", E},   CommandEntry{"RMIBL", E},   CommandEntry{"RMEBL", E},
    CommandEntry{"RMNBL", E},
    // Sum/setup offsets, tool length and working area in other systems, online tool offset,
    // 3-D compensation variants, exact-stop criteria of positioning axes, punching, repositioning
    // (Fundamentals, Job Planning): valid, not modelled, warned by name.
    CommandEntry{"DL", N},      CommandEntry{"TOWSTD", N},  CommandEntry{"TOWMCS", N},
    CommandEntry{"TOWWCS", N},  CommandEntry{"TOWBCS", N},  CommandEntry{"TOWTCS", N},
    CommandEntry{"TOWKCS", N},  CommandEntry{"WALCS0", N},  CommandEntry{"WALCS1", N},
    CommandEntry{"WALCS2", N},  CommandEntry{"WALCS3", N},  CommandEntry{"WALCS4", N},
    CommandEntry{"WALCS5", N},  CommandEntry{"WALCS6", N},  CommandEntry{"WALCS7", N},
    CommandEntry{"WALCS8", N},  CommandEntry{"WALCS9", N},  CommandEntry{"WALCS10", N},
    CommandEntry{"FTOCON", N},  CommandEntry{"FTOCOF", N},  CommandEntry{"CUT3DCC", N},
    CommandEntry{"CUT3DCCD", N}, CommandEntry{"CUTCONON", N}, CommandEntry{"CUTCONOF", N},
    CommandEntry{"FINEA", N},   CommandEntry{"COARSEA", N}, CommandEntry{"IPOENDA", N},
    CommandEntry{"PDELAYON", N}, CommandEntry{"PDELAYOF", N}, CommandEntry{"SPOF", N},
    CommandEntry{"SON", N},     CommandEntry{"SONS", N},    CommandEntry{"PON", N},
    CommandEntry{"PONS", N},    CommandEntry{"SPP", N},     CommandEntry{"SPN", N},
    CommandEntry{"REPOSA", N},  CommandEntry{"REPOSL", N},  CommandEntry{"REPOSQ", N},
    CommandEntry{"REPOSQA", N}, CommandEntry{"REPOSH", N},  CommandEntry{"REPOSHA", N},
    CommandEntry{"DISPR", N},   CommandEntry{"SCPARA", N},  // SCPARA[ax]=: servo parameter set
    // Approach/retract variants and 3-D variants drycut plans as their plain counterpart:
    // KONTC/KONTT (polynomial approach) as KONT with a warning, CDOF2 as CDOF (it differs only
    // in 3-D circumferential milling, CUT3DC), TCOFRX/Y/Z as TCOFR.
    CommandEntry{"KONTC", M},   CommandEntry{"KONTT", M},   CommandEntry{"CDOF2", M},
    CommandEntry{"TCOFRX", M},  CommandEntry{"TCOFRY", M},  CommandEntry{"TCOFRZ", M},
};

// Addresses with a value. Single letters plus the extended addresses of the 840D.
constexpr std::array<std::string_view, 60> kAddresses{
    "X", "Y", "Z", "A", "B", "C", "U", "V", "W", "I", "J", "K", "F", "S", "D", "H", "T", "E", "Q",
    "I1", "J1", "K1", "PW", "SD", "PL", "CR", "AR", "AP", "RP", "RPL", "TURN", "DISC", "OFFN", "S1",
    "S2", "H1", "H2", "A1", "A2", "ADIS", "ADISPOS", "LIMS", "SF", "OVR",
    "CTOL", "ATOL", "RND", "RNDM", "CHF", "CHR", "FRC", "FRCM", "FZ", "FB", "SVC", "ANG", "FP",
    "DISR", "DISCL", "FAD"};

// Words of the language itself, for the misspelling check.
constexpr std::array<std::string_view, 33> kKeywords{
    "GOTOF", "GOTOB", "GOTOC", "GOTO", "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR",
    "ENDFOR", "REPEAT", "UNTIL", "LOOP", "ENDLOOP", "CALL", "DEF", "PROC", "RET", "SAVE",
    "DISPLOF", "TO", "CASE", "OF", "DEFAULT", "REPEATB", "EXTERN", "DEFINE", "SETAL",
    "WHEN", "WHENEVER", "SETINT", "ENABLE"};

// G groups with the internal numbers of their G codes (PGA Fundamentals, "List of G
// functions"): G[group]=n selects the n-th, $P_GG[group] reads it.
struct GGroup {
  int group;
  std::array<int, 13> codes;  // 0: end of the list
};
constexpr std::array kGGroups{
    GGroup{1, {0, 1, 2, 3}},                                   // G0 G1 G2 G3 (then CIP, splines ...)
    GGroup{6, {17, 18, 19}},                                   // planes
    GGroup{7, {40, 41, 42}},                                   // tool radius compensation
    GGroup{8, {500, 54, 55, 56, 57}},                          // settable zero offsets (G505.. follow)
    GGroup{10, {60, 64, 641, 642, 643, 644, 645}},             // exact stop / continuous path
    GGroup{12, {601, 602, 603}},                               // exact-stop window
    GGroup{13, {70, 71, 700, 710}},                            // inch / metric
    GGroup{14, {90, 91}},                                      // absolute / incremental
    GGroup{15, {93, 94, 95, 96, 97, 931, 961, 971, 942, 952, 962, 972, 973}},  // feed types
    GGroup{18, {450, 451}},                                    // corner behaviour with TRC
};

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Levenshtein distance with an early cap; words here are short.
size_t edit_distance(std::string_view a, std::string_view b) {
  std::array<size_t, 64> prev{}, cur{};
  if (a.size() >= prev.size() || b.size() >= prev.size()) return 99;
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0u : 1u)});
    prev = cur;
  }
  return prev[b.size()];
}

}  // namespace

std::span<const CommandInfo> all_commands() { return kCommands; }
std::span<const std::string_view> all_addresses() { return kAddresses; }

bool is_transformation_command(std::string_view upper_name) {
  return upper_name == "TRANSMIT" || upper_name == "TRACYL" || upper_name == "TRAANG" || upper_name == "TRAORI" ||
         upper_name == "TRAFOOF";
}

Support command_support(std::string_view name) {
  // Every name word of every block asks: one hash lookup, not a walk through the table.
  static const std::unordered_map<std::string_view, Support> kByName = [] {
    std::unordered_map<std::string_view, Support> m;
    for (const auto& c : kCommands) m.emplace(c.name, c.support);
    return m;
  }();
  if (const auto it = kByName.find(name); it != kByName.end()) return it->second;
  // GFRAME0 ... GFRAME100 (G group 64, grinding frames; Fundamentals, list of G groups).
  if (name.size() > 6 && name.size() <= 9 && name.substr(0, 6) == "GFRAME") {
    int n = 0;
    for (const char c : name.substr(6)) {
      if (c < '0' || c > '9') return Support::Unknown;
      n = n * 10 + (c - '0');
    }
    if (n <= 100) return Support::NotModelled;
  }
  // Standard cycles (CYCLE81, CYCLE800, POCKET3 ...) are not here: they are subprogram calls,
  // found in the user's folders first, then in drycut's own NC cycles (programs/cycles).
  return Support::Unknown;
}

Support g_code_support(int64_t g) {
  // Modelled: motion, planes, TRC, offsets, exact stop / continuous path, units, dimensions,
  // feed types, polar poles, corner behaviour.
  switch (g) {
    case 0: case 1: case 2: case 3: case 4: case 9: case 17: case 18: case 19: case 40: case 41:
    case 42: case 53: case 54: case 55: case 56: case 57: case 60: case 64: case 70: case 71:
    case 90: case 91: case 94: case 95: case 110: case 111: case 112: case 153: case 450: case 451:
    case 500: case 601: case 602: case 603: case 641: case 642: case 643: case 644: case 645:
    case 700: case 710:
    case 33: case 34: case 35: case 63: case 93: case 96: case 97: case 331: case 332:  // threads, feed types
    case 961: case 962: case 971: case 972: case 973:  // G96/G97 with the feed type linear or kept
    case 291:  // ISO dialect mode: the interpreter stops with 990006 (it would misread what follows)
      return M;
    case 290:  // Siemens mode: the mode drycut reads anyway
      return E;
    case 25: case 26:  // spindle speed limits (G25/G26 S); with axis words: working area, warned
      return M;
    case 58: case 59:  // axial programmable offsets (the interpreter's frame chain)
      return M;
    case 5: case 7: case 8:
    case 74: case 75:  // reference point / fixed point approach (the interpreter)
      return M;
    case 140: case 141: case 142: case 143: case 147: case 148: case 247: case 248:
    case 340: case 341: case 347: case 348:  // smooth approach and retraction (interp/smooth_approach.hpp)
      return M;
    case 460: case 461: case 462: case 62: case 621:
    case 751: case 752: case 810: case 811: case 812: case 813: case 814: case 815: case 816:
    case 817: case 818: case 819: case 820: case 821: case 822: case 823: case 824: case 825:
    case 826: case 827: case 828: case 829: case 931: case 942: case 952:
      return N;
    default:
      if (g >= 505 && g <= 599) return M;  // settable zero offsets
      return Support::Unknown;
  }
}

// G groups whose members are named commands, in the order of their internal numbers (PGA
// Fundamentals, "List of G functions": group 16 feed on curves with TRC, 17 approach and
// retraction with TRC, 21 acceleration profile, 23 collision monitoring, 29 radius/diameter,
// 30 compressor, 59 dynamic response modes).
struct NamedGGroup {
  int group;
  std::array<std::string_view, 6> names;  // empty: end of the list
};
constexpr std::array kNamedGGroups{
    NamedGGroup{16, {"CFC", "CFTCP", "CFIN"}},
    NamedGGroup{17, {"NORM", "KONT", "KONTT", "KONTC"}},
    NamedGGroup{21, {"BRISK", "SOFT", "DRIVE"}},
    NamedGGroup{23, {"CDOF", "CDON", "CDOF2"}},
    NamedGGroup{29, {"DIAMOF", "DIAMON", "DIAM90", "DIAMCYCOF"}},
    NamedGGroup{30, {"COMPOF", "COMPON", "COMPCURV", "COMPCAD", "COMPSURF"}},
    NamedGGroup{59, {"DYNNORM", "DYNPOS", "DYNROUGH", "DYNSEMIFIN", "DYNFINISH", "DYNPREC"}},
};

std::string_view named_code_of_group(int group, int index) {
  for (const auto& g : kNamedGGroups)
    if (g.group == group && index >= 1 && index <= static_cast<int>(g.names.size())) return g.names[static_cast<size_t>(index - 1)];
  return {};
}

int g_code_of_group(int group, int index) {
  if (group == 8 && index >= 6 && index <= 100) return 505 + (index - 6);  // G505 .. G599
  for (const auto& g : kGGroups) {
    if (g.group != group) continue;
    int n = 0;
    for (size_t i = 0; i < g.codes.size(); ++i) {
      if (i > 0 && g.codes[i] == 0) break;
      if (++n == index) return g.codes[i];
    }
  }
  return -1;
}

bool g_group_of_code(int code, int& group, int& index) {
  if (code >= 505 && code <= 599) {
    group = 8;
    index = 6 + (code - 505);
    return true;
  }
  for (const auto& g : kGGroups)
    for (size_t i = 0; i < g.codes.size(); ++i) {
      if (i > 0 && g.codes[i] == 0) break;
      if (g.codes[i] == code) {
        group = g.group;
        index = static_cast<int>(i) + 1;
        return true;
      }
    }
  return false;
}

bool g_group_of_name(std::string_view name, int& group, int& index) {
  if (name.size() > 1 && name[0] == 'G' && all_digits(name.substr(1))) {
    int code = 0;
    for (const char c : name.substr(1)) code = code * 10 + (c - '0');
    return name.size() <= 5 && g_group_of_code(code, group, index);
  }
  for (const auto& g : kNamedGGroups)
    for (size_t i = 0; i < g.names.size() && !g.names[i].empty(); ++i)
      if (g.names[i] == name) {
        group = g.group;
        index = static_cast<int>(i) + 1;
        return true;
      }
  return false;
}

bool is_axis_indexed_command(std::string_view name) {
  return name == "DIAMONA" || name == "DIAMOFA" || name == "DIAM90A" || name == "DIACYCOFA" ||
         name == "DIAMCHANA" || name == "SCC" || name == "FOCON" || name == "FOCOF";
}

bool is_extended_address(std::string_view name) {
  if (name.size() < 2 || std::string_view("XYZABCUVWSHDTEQ").find(name[0]) == std::string_view::npos) return false;
  return all_digits(name.substr(1));
}

bool is_address(std::string_view name) {
  // The one-letter addresses are most of every program: answered without the table.
  if (name.size() == 1) return is_address_letter(name[0]);  // a jump, not a library search of the letters
  return std::find(kAddresses.begin(), kAddresses.end(), name) != kAddresses.end();
}

std::string_view near_miss(std::string_view name) {
  if (name.size() < 3) return {};
  const size_t limit = name.size() >= 6 ? 2 : 1;
  std::string_view best;
  size_t best_distance = limit + 1;
  auto consider = [&](std::string_view candidate) {
    const size_t d = edit_distance(name, candidate);
    if (d > 0 && d < best_distance) {
      best = candidate;
      best_distance = d;
    }
  };
  for (const auto& c : kCommands) consider(c.name);
  for (auto k : kKeywords) consider(k);
  return best;
}

}  // namespace drycut::parser
