#include "parser/language_table.hpp"

#include <array>

#include "parser/function_table.hpp"
#include "parser/system_variables.hpp"

namespace drycut::parser {
namespace {

constexpr Support M = Support::Modelled;
constexpr Support N = Support::NotModelled;
constexpr Support E = Support::NoEffect;

struct Row {
  const char* name;
  Support support;
  const char* meaning;
};

// Block structure and statements: decided by the lexer, line parser and loader (PGA
// Fundamentals "Program structure"; Job Planning "Flexible NC programming", "Program flow").
constexpr std::array kSyntax{
    Row{"N10 / :10", M, "block number, main block number"},
    Row{"LABEL:", M, "jump label (two letters or _ first)"},
    Row{"/ /0 ... /9", M, "block skip levels (all off unless set)"},
    Row{"; comment", M, "comment to the end of the line"},
    Row{"N10G1X10Y20", M, "compact blocks: one letter and a digit begin an address word, which ends with its digits"},
    Row{"X=expr", M, "address with an expression; AC() IC(); for rotary axes DC() ACP() ACN() (docs/axes.md)"},
    Row{"POS[ax]= POSA[ax]= FA[ax]= WAITP(ax)", M, "positioning axes on their own interpolator, their feed, waiting for them"},
    Row{"ACC[ax]= VELOLIM[ax]= JERKLIM[ax]=", M, "an axis's acceleration (1-200 %), velocity (1-100 %) and jerk (1-200 %) limits, modal (docs/controller-state.md \"Programmable dynamic limits\")"},
    Row{"SPOS= SPOS[n]= SPOSA= WAITS M19", M, "spindle positioning (position control) and waiting for it"},
    Row{"FGROUP(ax, ...)", M, "the axes whose travel the path feed F refers to"},
    Row{"POLY PO[ax]=(end, a2, a3, a4, a5) PL=", M, "polynomial interpolation (degree <= 5 per axis, p in [0, PL], PL default 1); PO[]=(b2..b4), the denominator, is warned and planned straight (docs/controller-state.md \"Polynomial interpolation\")"},
    Row{"DIAMONA[ax] DIAMOFA[ax] DIAM90A[ax] DIACYCOFA[ax] DIAMCHANA[ax] SCC[ax]", M, "axis-specific diameter programming; the reference axis of G96 (docs/controller-state.md \"Diameter programming\")"},
    Row{"$P_UIFR[n]=CTRANS(..) / $P_UIFR[n,ax,TR|FI|RT|SC|MI]=v / $P_PFRAME=CROT(..)", M, "settable frame (effective at its next selection) and programmable frame (at once), whole or by component"},
    Row{"X1= S1= M2=3 H7=40", M, "extended addresses: axis names, spindle/auxiliary function numbers"},
    Row{"G[group]=n", M, "indirect G code by group and internal number (groups 1 6 7 8 10 12 13 14 15 18, named 21 30 59)"},
    Row{"M[n]= S[n]= H[n]= T[n]= D[n]=", M, "address extension as an expression"},
    Row{"M1010 M=QU(1500) M1=1000", M,
        "M values are INT, 0..2147483647 (Fundamentals, \"Auxiliary functions\", value range of M; machine builders' "
        "functions above 999 are common); a value outside is 12160. Until 2026-11-29 every M above 999 was refused "
        "(conformance `language/m_function_above_999.mpf`)"},
    Row{"AX[axis]=", M, "axis given by an AXIS value"},
    Row{"1.5EX3, 'H1F', 'B101'", M, "exponent, hexadecimal and binary constants"},
    Row{"\"text\"", M, "string constant"},
};

constexpr std::array kStatements{
    Row{"DEF INT/REAL/BOOL/CHAR/STRING[n]/AXIS/FRAME", M, "local variables, scalars and arrays [a] [a,b] [a,b,c], = value, =(list), =SET(list), =REP(v)"},
    Row{"DEF NCK / DEF CHAN", M, "global variables (GUD) in definition files (.DEF beside the program or --definitions)"},
    Row{"DEFINE name AS text", M, "macro (in definition files or the program)"},
    Row{"PROC name(type p, VAR type q, type r[n]) SAVE DISPLOF SBLOF", M, "subprogram with value and reference parameters; SAVE restores the caller's modal G functions and frames"},
    Row{"EXTERN name(types)", M, "declaration of a subprogram with parameters (nothing to execute)"},
    Row{"name / name(args) / L123 / CALL \"name\" / name P3", M, "subprogram calls (16 levels), passes"},
    Row{"RET / M17 / M2 / M30", M, "end of subprogram / program (M2, M30 in a called program return to the caller, as M17)"},
    Row{"IF ... ELSE ... ENDIF", M, "structured condition"},
    Row{"WHILE ... ENDWHILE", M, "loop"},
    Row{"FOR v = a TO b ... ENDFOR", M, "counting loop (INT/REAL variable or R parameter)"},
    Row{"REPEAT ... UNTIL cond", M, "loop"},
    Row{"LOOP ... ENDLOOP", M, "endless loop (left by a jump)"},
    Row{"GOTOF / GOTOB / GOTO / GOTOC target", M, "jumps to a label, block number, STRING variable or string expression"},
    Row{"GOTOS", M, "back to the first block of the program (after its definitions)"},
    Row{"IF cond GOTOx target", M, "conditional jump; several in one block: the first whose condition holds (GOTOF :30 jumps to main block 30)"},
    Row{"CASE expr OF c GOTOx l ... DEFAULT GOTOx l", M, "multi-way jump"},
    Row{"REPEAT start [end] P=n / REPEATB label P=n / ENDLABEL:", M, "program section repetition"},
    Row{"CALL BLOCK start TO end", M, "the program section between the labels runs once (as REPEAT start end); a label may be a STRING variable or constant"},
    Row{"CALL \"PROG\" BLOCK start TO end", M, "that section of program PROG runs, then the call returns"},
    Row{"REDEF name attributes", M, "new access rights, preprocessing stop, initialisation or limits of a name (definition files): accepted, nothing changes"},
    Row{"SETAL(n[, text])", M, "cycle/user alarm: 62000-62999 and 67000-67999 only display (warning), the rest of 60000-69999 stop the program"},
    Row{"MSG(text)", M, "message (composed with <<)"},
    Row{"EXECSTRING(text)", M, "the string runs as a program line of its own after this line"},
    Row{"STOPRE", M, "preprocessing stop"},
    Row{"ID=n WHEN/WHENEVER/FROM/EVERY ... DO ...", N, "synchronized actions: accepted, not simulated"},
    Row{"SETINT(n) PRIO=m NAME / ENABLE / DISABLE / CLRINT", N, "interrupt routines: accepted, never triggered in a dry run"},
    Row{"MCALL name(args) / MCALL", M, "modal call after every block with axis motion (not inside the called program); MCALL alone ends it"},
    Row{"DRYCUT_CONTOUR_BEGIN / DRYCUT_CONTOUR_END / DRYCUT_CONTOUR_CALL(\"NAME\", \"START:END\" or \"PROG:START:END\") / $DRYCUT_CONTOUR_N / $DRYCUT_CONTOUR[i,k]", M, "drycut's own, for its contour cycles (CYCLE95): record the contour of the blocks between, without moving, and read it (docs/cycles.md \"Contour cycles\")"},
    Row{"PCALL / EXTCALL", M, "calls with a path / from external memory: run as CALL from drycut's folders (the path is dropped); EXTCALL takes a STRING expression (\"PAL\" << R1); a name may carry the prefix _N_ and the extension _SPF/_MPF in any combination"},
};

constexpr std::array kOperators{
    Row{"+ - * / DIV MOD", M, "arithmetic (DIV integer division, MOD remainder)"},
    Row{"== <> < > <= >=", M, "comparison (REAL: relative tolerance 1e-12), strings compare as text"},
    Row{"AND OR XOR NOT", M, "logic"},
    Row{"B_AND B_OR B_XOR B_NOT", M, "bit operations on integers"},
    Row{"<<", M, "string concatenation (numbers converted, up to 10 significant digits)"},
    Row{"precedence", M, "NOT B_NOT - | * / DIV MOD | + - | B_AND | B_XOR | B_OR | AND | XOR | OR | << | comparisons"},
};

void add(std::vector<LanguageFeature>& out, const char* section, std::string name, Support s, std::string meaning) {
  out.push_back(LanguageFeature{section, std::move(name), s, std::move(meaning)});
}

}  // namespace

std::string_view support_text(Support s) {
  switch (s) {
    case Support::Modelled: return "modelled";
    case Support::NoEffect: return "modelled (no effect on a dry run)";
    case Support::NotModelled: return "accepted, warning 990002";
    default: return "refused";
  }
}

std::vector<LanguageFeature> language_features() {
  std::vector<LanguageFeature> out;
  for (const Row& r : kSyntax) add(out, "Blocks and addresses", r.name, r.support, r.meaning);
  for (const Row& r : kStatements) add(out, "Statements", r.name, r.support, r.meaning);
  for (const Row& r : kOperators) add(out, "Operators", r.name, r.support, r.meaning);
  for (const FunctionInfo& f : all_functions()) {
    const bool frame = f.func == Function::FrameFunction;
    if (f.func == Function::Assumed) {  // valid, not computed: the result a call that went well gives
      const std::string result = f.assumed.starts_with('#') ? "argument " + std::string(f.assumed.substr(1))
                                 : f.assumed == "FRAME"     ? "the null frame"
                                                            : std::string(f.assumed);
      add(out, "Functions", std::string(f.name), Support::NotModelled, std::string(f.meaning) + "; result taken: " + result);
      continue;
    }
    add(out, "Functions", std::string(f.name), Support::Modelled,
        std::string(f.meaning) + (frame ? " (computed where $P_UIFR/$P_PFRAME is written; `:` chains them)" : ""));
  }
  for (const CommandInfo& c : all_commands()) add(out, "Commands", std::string(c.name), c.support, "");
  add(out, "Commands", "CYCLEnnn, POCKETn, SLOTn, HOLESn ...", Support::Modelled,
      "standard cycles: NC subprograms shipped in programs/cycles (docs/cycles.md); a cycle in the user's folders wins");
  for (int g = 0; g < 1000; ++g) {
    const Support s = g_code_support(g);
    if (s == Support::Unknown || (g > 505 && g < 599)) continue;
    add(out, "G codes", g == 505 ? "G505 ... G599" : "G" + std::to_string(g), s, "");
  }
  for (std::string_view a : all_addresses()) add(out, "Addresses", std::string(a), Support::Modelled, "");
  const std::array<std::pair<const char*, const char*>, 7> sysvars{{
      {"$MN_ $MC_ $MA_[axis] $MM_", "machine data: the profile's value (its fields under their MD names, and its machine_data map), a few unmodelled data at their documented defaults; unknown: 0 and warning 990007"},
      {"$SN_ $SC_ $SA_[axis]", "setting data: as machine data"},
      {"$P_ $AA_ $AC_ $VA_ $A_", "programmed and actual state from the interpreter ($P_GG[g], $P_EP[ax], $AA_IM[ax], $P_F, $P_TOOLNO, $P_TOOL, $P_TOOLR, $P_AD[n] ...); unknown names: 0"},
      {"$A_IN $A_OUT $A_INA $A_OUTA $A_DBB $A_DBW $A_DBD $A_DBR", "inputs, outputs, PLC data: the profile's machine_data map, default 0"},
      {"$TC_DP3 $TC_DP6 [t, d] and other $TC_", "tool data: the run's tool table (type $TC_DP1, edge position $TC_DP2, lengths $TC_DP3..5, radius $TC_DP6, their wear $TC_DP12..15, base lengths $TC_DP21..23; the teeth $TC_DPNT for G95 FZ); written values are kept"},
      {"$TC_CARR<k>[1] / $DRYCUT_SWIVEL_DATUM[k]", "swivel data record 1 (CYCLE800): the profile's machine_data ($TC_CARR23 from swivel_kinematics); $DRYCUT_SWIVEL_DATUM[k] is 1 when the profile gives $TC_CARR<k>[1] (docs/cycles.md \"CYCLE800\")"},
      {"any other $ name", "0 and warning 990007 (a write is kept)"},
  }};
  for (const auto& [name, meaning] : sysvars) add(out, "System variables", name, Support::Modelled, meaning);
  return out;
}

std::string language_markdown() {
  std::string md =
      "# The NC language in drycut\n\n"
      "Generated by `drycut language --markdown` from the tables the parser decides with; a test\n"
      "keeps this file equal to that output. Every row is **modelled** (drycut does what the\n"
      "control does), **modelled (no effect on a dry run)** (the control's effect is on display,\n"
      "single block or buffering, nothing a dry run measures), or **accepted, warning 990002**\n"
      "(valid on the control, not simulated: the run goes on and the warning names it). A word in\n"
      "no row is refused with the control's alarm (12550 name not defined, 12470 G function\n"
      "unknown, 12080 syntax error ...). The rules behind the rows, with their sources, are in\n"
      "docs/language-rules.md; the conformance programs in tests/conformance/language/.\n";
  std::string section;
  for (const LanguageFeature& f : language_features()) {
    if (f.section != section) {
      section = f.section;
      md += "\n## " + section + "\n\n| name | drycut | meaning |\n|---|---|---|\n";
    }
    std::string name = f.name;
    std::string escaped;
    for (char c : name) {
      if (c == '|') escaped += "\\|";
      else escaped += c;
    }
    md += "| `" + escaped + "` | " + std::string(support_text(f.support)) + " | " + f.meaning + " |\n";
  }
  return md;
}

}  // namespace drycut::parser
