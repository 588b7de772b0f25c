// The words of an ordinary block become a Block: G and M words, addresses (plain, extended
// X1= / H7= / S1=, indirect G[group]= / M[n]= / S[n]= / H[n]=, AX[axis]=), variable and system
// variable assignments, modelled commands with their arguments, SETAL, and at most one
// subprogram call (by name, L number or with arguments) with P passes.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <tuple>

#include "parser/command_table.hpp"
#include "parser/expression_parser.hpp"
#include "parser/line_error.hpp"
#include "parser/loader_frame.hpp"

namespace drycut::parser {

class ProgramLoader::BlockBuilder {
 public:
  BlockBuilder(ProgramLoader& loader, Block& out) : l_(loader), out_(out), f_(*loader.frames_.back()) {}

  bool build() {
    // The file outlives clear(): blocks come from the file of the one before.
    const FileName file = out_.file;
    out_.clear();
    out_.file = file;
    for (const Item& item : l_.parsed_.items) {
      switch (item.kind) {
        case ItemKind::G: g_word(item, item.code); break;
        case ItemKind::M: m_word(item); break;
        case ItemKind::Address: address(item); break;
        case ItemKind::Assign: assignment(item); break;
        case ItemKind::Procedure: procedure(item); break;
        case ItemKind::Name: name(item); break;
        case ItemKind::ToolName: tool_by_name(std::string(item.name), item.column); break;
        case ItemKind::LCall: set_call(item.name, item.column); break;
        case ItemKind::Passes: passes_ = static_cast<uint64_t>(std::max<int64_t>(1, item.code)); break;
      }
    }
    return finish();
  }

 private:
  void g_word(const Item& item, int64_t code) {
    const Support s = g_code_support(code);
    if (s == Support::Unknown) throw LineError(12470, item.column, "G" + std::to_string(code));
    if (s == Support::NotModelled) {
      l_.warn_not_modelled("G" + std::to_string(code), item.column);
      return;
    }
    out_.g.push_back(GWord{static_cast<int>(code), item.column});
    l_.g_used_.set(static_cast<size_t>(code));
    has_words_ = true;
  }

  void m_word(const Item& item) { add_m(item, item.code, item.expr, item.extension); }

  // M3, M4 and M5 of one spindle are one auxiliary function group: two different ones in a
  // block (M3 S1000 M5) are alarm 14760; the same spindle written with and without its number
  // (M3 M1=5) is not recognised here (the master spindle is the interpreter's).
  void refuse_second_spindle_direction(const Item& item, int64_t code, int extension) const {
    if (code < 3 || code > 5) return;
    for (const MWord& m : out_.m)
      if (m.code >= 3 && m.code <= 5 && m.code != code && m.extension == extension)
        throw LineError(14760, item.column,
                        "M" + std::to_string(m.code) + " and M" + std::to_string(code) +
                            " of one spindle in a block (one auxiliary function group)");
  }

  void add_m(const Item& item, int64_t code, ExprIndex expr, int extension) {
    // M is an INT auxiliary function value, 0..2147483647 (Fundamentals, "Auxiliary functions":
    // machine builders' M functions above 999, M1010 or M=QU(1500), are ordinary; until
    // 2026-11-29 drycut refused every M above 999 with 12160).
    constexpr double kMaxM = 2147483647.0;
    if (expr != kNoExpr) {
      const double v = l_.eval(expr);
      if (v < 0 || v != std::trunc(v) || v > kMaxM) throw LineError(12160, item.column, "M value must be an integer 0..2147483647");
      code = static_cast<int64_t>(v);
    }
    if (code > static_cast<int64_t>(kMaxM)) throw LineError(12160, item.column, "M value must be an integer 0..2147483647");
    refuse_second_spindle_direction(item, code, extension);
    out_.m.push_back(MWord{static_cast<int>(code), extension, item.column});
    if (code < static_cast<int64_t>(l_.m_used_.size()))
      l_.m_used_.set(static_cast<size_t>(code));
    else
      l_.commands_used_.insert("M" + std::to_string(code));
    has_words_ = true;
    if (code == 17) action_ = PendingAction::Return;
    // At M0 the operator may change values (R parameters) before restarting: a loop through the
    // stop that repeats waits for the operator, it is not endless. (M1 is optional: not counted.)
    if (code == 0) l_.system_variables_.note_external_read("the operator at M0");
    if (code == 2 || code == 30) {
      // In a called program M2/M30 end it and return to the calling level, as M17 does
      // (Fundamentals, "Subprograms": a subprogram, like a main program, may end with M2; there
      // it means the return): main programs called from a collector program run one after the other.
      if (l_.frames_.size() > 1) {
        out_.m.back().code = 17;
        action_ = PendingAction::Return;
      } else {
        action_ = PendingAction::EndProgram;
      }
    }
  }

  // An address may stand once in a block (X10 X20, F100 F200: the control refuses, it does not
  // take the last); H, an auxiliary function, up to three times.
  void refuse_repeated(std::string_view name, uint32_t column) const {
    if (name == "H") return;
    if (name == "T" && out_.tool_name) throw LineError(12000, column, "address T programmed twice in the block");
    // Size and first letter before the full compare: this runs for every word of every block,
    // and a memcmp call per pair of one-letter names was 6 % of a G1 run.
    for (const AddressWord& a : out_.addresses)
      if (a.name.size() == name.size() && !name.empty() && a.name[0] == name[0] && a.name == name)
        throw LineError(12000, column, "address " + std::string(name) + " programmed twice in the block");
  }

  // T="NAME" (tool management): T once per block, by name or number (T="A" M6 T="B": the
  // control refuses the block, as T1 T2).
  void tool_by_name(std::string name, uint32_t column) {
    refuse_repeated("T", column);
    out_.tool_name = std::move(name);
    has_words_ = true;
  }

  void address(const Item& item) {
    if (item.name.size() == 1 ? !is_address_letter(item.name[0]) : !is_address(item.name))
      throw LineError(12550, item.column, "address " + std::string(item.name) + " not defined");
    refuse_repeated(item.name, item.column);
    AddressWord& w = out_.addresses.emplace_back();  // no temporary: the hot path of every block
    w.name.assign(item.name);
    w.value = l_.parsed_.pool[item.expr].value;
    w.column = item.column;
    has_words_ = true;
  }

  // X=R1*2, X=AC(5), X=IC(-1), C=DC(0), A=ACP(90): the value and how it was written.
  std::pair<double, ValueMode> moded_value(const Item& item) {
    const ExprNode& top = l_.parsed_.pool[item.expr];
    ValueMode mode = ValueMode::Default;
    if (top.op == ExprOp::Call) {
      switch (top.func) {
        case Function::AbsoluteMode: mode = ValueMode::Absolute; break;
        case Function::IncrementalMode: mode = ValueMode::Incremental; break;
        case Function::DirectMode: mode = ValueMode::Direct; break;
        case Function::AbsolutePositive: mode = ValueMode::AbsolutePositive; break;
        case Function::AbsoluteNegative: mode = ValueMode::AbsoluteNegative; break;
        case Function::DiameterAbsolute: mode = ValueMode::DiameterAbsolute; break;
        case Function::DiameterIncremental: mode = ValueMode::DiameterIncremental; break;
        case Function::RadiusAbsolute: mode = ValueMode::RadiusAbsolute; break;
        case Function::RadiusIncremental: mode = ValueMode::RadiusIncremental; break;
        case Function::PerMinute: case Function::PerRevolution:
          // The feed type of FAD alone (Fundamentals, "Smooth approach and retraction").
          if (item.name != "FAD") throw LineError(12080, item.column, std::string(top.text) + "() only with FAD=");
          mode = top.func == Function::PerMinute ? ValueMode::PerMinute : ValueMode::PerRevolution;
          break;
        default: break;
      }
      if (mode != ValueMode::Default) return {l_.eval(l_.parsed_.pool.args[top.a]), mode};
    }
    return {l_.eval(item.expr), mode};
  }

  void address_value(std::string name, const Item& item) {
    refuse_repeated(name, item.column);
    const auto [value, mode] = moded_value(item);
    out_.addresses.push_back(AddressWord{std::move(name), value, mode, item.column});
    has_words_ = true;
  }

  // POS[A]=90, POSA[C]=ACP(0), FA[A]=3600, SPOS=0, SPOS[2]=IC(90), SPOSA=180, ACC[X]=50.
  bool axis_word(const Item& item) {
    static constexpr std::pair<std::string_view, AxisWordKind> kWords[] = {
        {"POS", AxisWordKind::Pos}, {"POSA", AxisWordKind::PosA}, {"FA", AxisWordKind::AxialFeed},
        {"SPOS", AxisWordKind::SPos}, {"SPOSA", AxisWordKind::SPosA}, {"ACC", AxisWordKind::AccelPercent},
        {"VELOLIM", AxisWordKind::VelocityPercent}, {"JERKLIM", AxisWordKind::JerkPercent},
        {"FGREF", AxisWordKind::FeedReferenceRadius}};
    const auto* hit = std::find_if(std::begin(kWords), std::end(kWords), [&](const auto& w) { return w.first == item.name; });
    if (hit == std::end(kWords)) return false;
    const bool spindle = hit->second == AxisWordKind::SPos || hit->second == AxisWordKind::SPosA;
    AxisWord w;
    w.kind = hit->second;
    w.column = item.column;
    if (item.index_count == 1) {
      const Value index = l_.eval_value(l_.parsed_.pool.args[item.index_first]);
      if (spindle) w.axis = number_to_text(as_number(index, item.column));
      else if (index.kind == ValueKind::Axis || index.is_text()) w.axis = index.text;
      else throw LineError(12150, item.column, std::string(item.name) + "[...] needs an axis");
    } else if (item.index_count == 0 && spindle) {
      w.axis.clear();  // the master spindle, whichever it is (SETMS): the interpreter knows
    } else {
      throw LineError(12410, item.column, std::string(item.name) + "[...] takes one axis");
    }
    std::tie(w.value, w.mode) = moded_value(item);
    out_.axis_words.push_back(std::move(w));
    has_words_ = true;
    return true;
  }

  void assignment(const Item& item) {
    // P= is the number of passes, unless the program defined a variable P (DEF INT P: a user
    // name as the manuals' PROC examples use X and Y; then P=7 assigns it, as T=, F= ... do).
    if (item.name == "P" && item.index == kNoExpr && item.index_count == 0 && !l_.find_variable("P")) {
      // At most 9999 passes; checked before the conversion (out of range it is undefined).
      const double p = l_.eval(item.expr);
      if (!(p <= 9999)) throw LineError(12160, item.column, "P (passes) must be at most 9999");
      passes_ = static_cast<uint64_t>(std::max(1.0, p));
      return;
    }
    if (item.index != kNoExpr) {  // R[i]=
      l_.assign_r_parameter(l_.eval(item.index), l_.eval(item.expr), item.column);
      return;
    }
    if (!item.name.empty() && item.name[0] == '$') {
      l_.assign_system_variable(item, out_);
      has_words_ = true;  // the interpreter applies what it models
      return;
    }
    if (Variable* v = l_.find_variable(item.name)) {
      // A list of values (POSP[2]=(1,2) to a user array named like a list command) is no value.
      if (item.expr == kNoExpr) throw LineError(12080, item.column, "a value expected, not a list");
      l_.assign_variable(*v, item.index_first, item.index_count, item.expr, item.column);
      return;
    }
    if (item.index_count == 0 && is_r_parameter_name(item.name)) {
      l_.assign_r_parameter(std::stod(std::string(item.name.substr(1))), l_.eval(item.expr), item.column);
      return;
    }
    if (item.name[0] == 'T' && item.index_count == 0 &&
        item.name.find_first_not_of("0123456789", 1) == std::string_view::npos) {
      // T=<STRING expression> under tool management (T=_NAME in a tool-change macro): a tool
      // name; T<n>="name" the same for spindle n (Fundamentals, "Tool change with T command":
      // the address extension is the spindle number, as in T1=5).
      const Value v = l_.eval_value(item.expr);
      if (v.is_text()) {
        if (item.name.size() > 1 && item.name.size() <= 3) out_.tool_name_spindle = std::stoi(std::string(item.name.substr(1)));
        tool_by_name(v.text, item.column);
        return;
      }
    }
    if (axis_word(item)) return;
    if (item.name == "PO") {
      polynomial(item);
      return;
    }
    if (item.name == "M" && item.index_count == 0) {  // M=QU(8), M=R10: the M function of the value
      add_m(item, 0, item.expr, 0);
      return;
    }
    if (item.name == "ATOL") {
      // ATOL[X]=0.01: the axis tolerance of the smoothing and the compressor (modal).
      if (item.index_count != 1) throw LineError(12410, item.column, "ATOL[...] takes one axis");
      const Value index = l_.eval_value(l_.parsed_.pool.args[item.index_first]);
      if (index.kind != ValueKind::Axis && !index.is_text()) throw LineError(12150, item.column, "ATOL[...] needs an axis");
      std::string axis = index.text;
      for (char& c : axis) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      address_value("ATOL[" + axis + "]", item);
      return;
    }
    if (!is_address(item.name)) {
      // OVR=50, CTOL=0.01: valid settings drycut does not model.
      const Support s = command_support(item.name);
      // TCARR=0 deselects the tool carrier: with none modelled, nothing to say.
      if (item.name == "TCARR" && item.index_count == 0 && l_.eval(item.expr) == 0) return;
      if (s == Support::NotModelled) {
        l_.warn_not_modelled(not_modelled_assignment(item), item.column);
        return;
      }
      if (s == Support::NoEffect) return;
    }
    if (item.index_count > 0) {
      indexed_address(item);
      return;
    }
    // An axis of the machine's own name (MD10000/MD20080: MZ=180, MAG=2) from the profile.
    if (is_address(item.name) || is_extended_address(item.name) || l_.is_axis_name(item.name)) {
      address_value(std::string(item.name), item);
      return;
    }
    throw LineError(12550, item.column, "name " + std::string(item.name) + " not defined");
  }

  // G[8]=2, M[2]=3, S[1]=1000, H[7]=40, AX[AXNAME("X")]=10, T[1]=5, D[1]=2
  void indexed_address(const Item& item) {
    // A name that is none of these is not defined, with any number of indices (_TBA[0,1]=1 for
    // the array _TAB: 12550, not 12410).
    static constexpr std::string_view kIndexed[] = {"G", "M", "S", "H", "T", "D", "LIMS", "AX"};
    if (std::find(std::begin(kIndexed), std::end(kIndexed), item.name) == std::end(kIndexed))
      throw LineError(12550, item.column, "name " + std::string(item.name) + " not defined");
    if (item.index_count != 1) throw LineError(12410, item.column, std::string(item.name) + "[...] takes one index");
    const Value index = l_.eval_value(l_.parsed_.pool.args[item.index_first]);
    if (item.name == "AX") {
      if (index.kind != ValueKind::Axis && !index.is_text()) throw LineError(12150, item.column, "AX[...] needs an axis");
      address_value(index.text, item);
      return;
    }
    const double n = index_from_real(as_number(index, item.column));
    if (!(n >= 0 && n <= 99)) throw LineError(12430, item.column, "index must be 0..99");
    const int k = static_cast<int>(n);
    if (item.name == "G") {
      const double code_index = l_.eval(item.expr);
      if (code_index == 0) {
        // Index 0 is no code of the group. drycut check reads $P_GG as 0 (it keeps no modal
        // state), so a macro restoring a saved group must not stop there: warned, nothing set.
        l_.warn_not_modelled("G[" + std::to_string(k) + "]=0 (no code of the group: nothing selected)", item.column);
        return;
      }
      // Range first: a double beyond int is undefined behaviour in the conversion.
      if (!(code_index >= 1 && code_index <= 999) || code_index != std::trunc(code_index))
        throw LineError(12475, item.column, "G[" + std::to_string(k) + "]=" + number_to_text(code_index));
      const int code = g_code_of_group(k, static_cast<int>(code_index));
      if (const std::string_view named = named_code_of_group(k, static_cast<int>(code_index)); !named.empty()) {
        Item word = item;  // G[21]=2: SOFT, as if written by name
        word.name = named;
        word.index_count = 0;
        name(word);
        return;
      }
      if (code < 0) {
        l_.warn_not_modelled("G[" + std::to_string(k) + "]=" + number_to_text(code_index) + " (G group)", item.column);
        return;
      }
      g_word(item, code);
      return;
    }
    if (item.name == "M") {
      add_m(item, 0, item.expr, k);
      return;
    }
    // LIMS[n]= the speed limit of spindle n (Fundamentals, "Constant cutting rate": up to four
    // spindles in one block, LIMS=300 LIMS[2]=450).
    if (item.name == "S" || item.name == "H" || item.name == "T" || item.name == "D" || item.name == "LIMS") {
      address_value(std::string(item.name) + std::to_string(k), item);
      return;
    }
  }

  CommandWord& add_command(const Item& item) {
    if (l_.commands_used_.find(item.name) == l_.commands_used_.end()) l_.commands_used_.emplace(item.name);
    has_words_ = true;
    CommandWord& c = out_.commands.emplace_back();
    c.name.assign(item.name);
    c.column = item.column;
    return c;
  }

  // A valid command drycut does not model (warned by name) or that changes nothing it plans:
  // not handed on, except a transformation (the interpreter suspends the software limits).
  bool skipped_command(const Item& item, Support s, bool call_form = false) {
    if (s == Support::NotModelled && call_form && l_.has_program(item.name)) {
      // A keyword that only takes a value (NUT=, XH=, THETA=) written as a call, with the
      // user's program of that name at hand (German shops name a slot program NUT): the call.
      l_.warn(990018, std::string(item.name) + " (the keyword " + std::string(item.name) + "=... of the control)",
              item.column);
      return false;
    }
    if (s == Support::NotModelled) {
      l_.warn_not_modelled(item.name, item.column);
      if (is_transformation_command(item.name)) add_command(item);
      return true;
    }
    return s == Support::NoEffect;
  }

  void procedure(const Item& item) {
    if (item.name == "SETAL") {
      set_alarm(item);
      return;
    }
    if (item.name == "RET") {
      parameterised_return(item);
      return;
    }
    if (item.name == "DRYCUT_CONTOUR_CALL") {
      contour_call(item);
      return;
    }
    if (item.name == "GETSELT" || item.name == "GETEXET") {
      tool_query(item);
      return;
    }
    if (item.name == "EXECSTRING") {
      exec_string(item);
      return;
    }
    const Support s = command_support(item.name);
    if (skipped_command(item, s, true)) return;
    if (s == Support::Modelled) {
      CommandWord& c = add_command(item);
      c.has_parentheses = true;
      for (uint32_t k = 0; k < item.arg_count; ++k) {
        const ExprIndex a = l_.parsed_.pool.args[item.arg_first + k];
        if (a == kNoExpr) {
          c.args.emplace_back(std::string());
          continue;
        }
        const Value v = l_.eval_value(a);
        if (v.is_number()) c.args.emplace_back(v.number);
        else c.args.emplace_back(v.text);  // strings, axis names (SPLINEPATH(1,X,Y,Z))
      }
      return;
    }
    if (is_expression_keyword(item.name))
      throw LineError(12080, item.column, "function " + std::string(item.name) + " used as a block word");
    set_call(item.name, item.column);  // a subprogram with parameters: SUB(1, 2)
    for (uint32_t k = 0; k < item.arg_count; ++k)
      call_args_.push_back(l_.call_argument(l_.parsed_.pool.args[item.arg_first + k]));
  }

  // DRYCUT_CONTOUR_CALL("NAME", "START:END" or "PROG:START:END"): the contour of drycut's contour
  // cycles runs as a call: the subprogram NAME, the section between the labels of the program
  // that called the cycle, or that section of program PROG (CYCLE95's NPP, CYCLE62's contour;
  // interp/contour_recording.hpp).
  void contour_call(const Item& item) {
    const ExprIndex a = item.arg_count == 1 ? l_.parsed_.pool.args[item.arg_first] : kNoExpr;
    if (a == kNoExpr) throw LineError(12080, item.column, "DRYCUT_CONTOUR_CALL needs a contour (\"NAME\" or \"START:END\")");
    std::string spec(trimmed(as_text(l_.eval_value(a))));
    for (char& c : spec) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    std::vector<std::string> parts;
    for (size_t from = 0;;) {
      const size_t colon = spec.find(':', from);
      parts.emplace_back(trimmed(std::string_view(spec).substr(from, colon == std::string::npos ? colon : colon - from)));
      if (colon == std::string::npos) break;
      from = colon + 1;
    }
    if (parts.size() > 3 || std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); }))
      throw LineError(12080, item.column, "DRYCUT_CONTOUR_CALL: no contour in \"" + spec + "\"");
    set_call(parts.size() == 1 ? parts[0] : spec, item.column);
    if (parts.size() == 3) section_program_ = parts[0];
    if (parts.size() >= 2) {
      section_start_ = parts[parts.size() - 2];
      section_end_ = parts.back();
    }
  }

  // EXECSTRING(text): the text runs as the next program line (Job Planning, "EXECSTRING");
  // alarms of it point at this line.
  void exec_string(const Item& item) {
    const ExprIndex a = item.arg_count == 1 ? l_.parsed_.pool.args[item.arg_first] : kNoExpr;
    if (a == kNoExpr) throw LineError(12080, item.column, "EXECSTRING needs the line to run as a string");
    const Value v = l_.eval_value(a);
    if (!v.is_text()) throw LineError(12150, item.column, "EXECSTRING needs a string");
    if (l_.pending_line_) throw LineError(12080, item.column, "two EXECSTRING in one block");
    l_.pending_line_ = v.text;
  }

  // GETSELT(VAR INT t[, spindle]) / GETEXET(VAR INT t[, spindle]): the T number of the tool
  // selected (the last T, which M6 will load) / of the tool in the spindle (Job Planning, tool
  // management "GETSELT", "GETEXET"), written into the variable or R parameter given. The spindle
  // is the master spindle's whatever is written (drycut has one tool carrier).
  void tool_query(const Item& item) {
    const ExprIndex a = item.arg_count >= 1 ? l_.parsed_.pool.args[item.arg_first] : kNoExpr;
    if (a == kNoExpr) throw LineError(12080, item.column, std::string(item.name) + " needs a variable for the T number");
    const CallArgument target = l_.call_argument(a);
    if (!target.r_parameter && (!target.variable || target.element == SIZE_MAX))
      throw LineError(12150, item.column, std::string(item.name) + ": the T number needs a variable, not a value");
    const auto r = l_.system_variables_.read(item.name == "GETSELT" ? "$P_TOOLP" : "$P_TOOLNO", {});
    const double t = r.value.is_number() ? r.value.number : 0.0;
    if (target.r_parameter) *target.r_parameter = t;
    else target.variable->set(target.element, Value(t), item.column);
  }

  // SETAL(n[, "text"]): a cycle or user alarm. 62000..62999 (Siemens cycles) and 67000..67999
  // (user cycles, their counterpart) are display alarms: shown, and the program goes on (a
  // warning here); the others stop the program (Cycles manual, "Alarms"; docs/language-rules.md).
  void set_alarm(const Item& item) {
    if (item.arg_count < 1) throw LineError(12080, item.column, "SETAL needs an alarm number");
    const double n = l_.eval(l_.parsed_.pool.args[item.arg_first]);
    if (!(n >= 60000 && n <= 69999) || n != std::trunc(n))
      throw LineError(12160, item.column, "SETAL: alarm number must be 60000..69999");
    std::string text = "user alarm";
    if (item.arg_count > 1) {
      const ExprIndex t = l_.parsed_.pool.args[item.arg_first + 1];
      if (t != kNoExpr) text = as_text(l_.eval_value(t));
    }
    if ((n >= 62000 && n <= 62999) || (n >= 67000 && n <= 67999)) {
      l_.warn(static_cast<int>(n), text, item.column);
      return;
    }
    // The program checks the machine (IF $A_IN[5]==0 SETAL(65000,"AIR PRESSURE")): with a signal
    // the dry run does not know, the alarm is the dry run's guess, not the machine's state.
    if (const std::string input = l_.alarm_decided_by_unknown_input(static_cast<int>(n)); !input.empty()) {
      const bool measured = input.starts_with("$AA_M");
      const bool by_action = input.ends_with("(written by a synchronized action)");
      l_.warn(990021, "SETAL(" + number_to_text(n) + ", \"" + text + "\") follows from " + input +
                          (measured    ? ", a measured value (a dry run touches nothing)"
                           : by_action ? ", which a dry run does not compute (synchronized actions are not run)"
                                       : ", which the profile does not give (give it in machine_data to model the signal)"),
              item.column);
      return;
    }
    throw LineError(static_cast<int>(n), item.column, text);
  }

  void name(const Item& item) {
    if (item.name == "MCALL") {  // the call in this block becomes modal; MCALL alone ends it
      mcall_ = true;
      return;
    }
    const Support s = command_support(item.name);
    if (skipped_command(item, s, true)) return;
    if (s == Support::Modelled) {
      CommandWord& c = add_command(item);
      if (item.name == "RET") action_ = PendingAction::Return;
      if (item.index_count > 0) c.args.emplace_back(axis_index_text(item));  // DIAMONA[X], SCC[X]
      return;
    }
    if (l_.find_variable(item.name) || is_address(item.name))
      throw LineError(12080, item.column, std::string(item.name) + " without a value");
    if (is_expression_keyword(item.name))
      throw LineError(12080, item.column, "operator " + std::string(item.name) + " outside an expression");
    if (!call_name_.empty()) {
      // Two bare words ("GOTOFF ENDE"): blame the one that looks like a misspelled command.
      std::string_view bad = item.name;
      uint32_t bad_column = item.column;
      std::string_view guess = near_miss(call_name_);
      if (!guess.empty()) {
        bad = call_name_;
        bad_column = call_column_;
      } else {
        guess = near_miss(item.name);
      }
      throw LineError(12550, bad_column, "name " + std::string(bad) + " not defined" +
                                             (guess.empty() ? "" : " (did you mean " + std::string(guess) + "?)"));
    }
    set_call(item.name, item.column);
  }

  // PO[X]=(end, a2 .. a5): the axis word X=end and the coefficients; PO[]=(b2 .. b4).
  void polynomial(const Item& item) {
    // PO[XH]/PO[YH]/PO[ZH] (ORICURVE's second curve), PO[PHI]/PO[PSI] (orientation angles),
    // PO[THT] (the tool's rotation): orientation polynomials of 5/6-axis programs (Job
    // Planning, "Orientation polynomials"); drycut does not model orientation: warned.
    if (item.index_count == 1) {
      const ExprNode& index = l_.parsed_.pool[l_.parsed_.pool.args[item.index_first]];
      static constexpr std::string_view kOrientation[] = {"XH", "YH", "ZH", "PHI", "PSI", "THT"};
      if (index.op == ExprOp::Name &&
          std::find(std::begin(kOrientation), std::end(kOrientation), index.text) != std::end(kOrientation)) {
        l_.warn_not_modelled("PO[" + std::string(index.text) + "] (orientation polynomial)", item.column);
        return;
      }
    }
    PolyWord w;
    w.column = item.column;
    if (item.index_count > 0) w.axis = axis_index_text(item);
    const uint32_t most = w.axis.empty() ? 3 : 5;
    if (item.arg_count < 1 || item.arg_count > most)
      throw LineError(12080, item.column, w.axis.empty() ? "PO[]=(b2, b3, b4) takes 1 to 3 values"
                                                         : "PO[" + w.axis + "]=(end, a2, a3, a4, a5) takes 1 to 5 values");
    for (uint32_t k = 0; k < item.arg_count; ++k) w.values.push_back(l_.eval(l_.parsed_.pool.args[item.arg_first + k]));
    if (!w.axis.empty()) out_.addresses.push_back(AddressWord{w.axis, w.values[0], ValueMode::Default, item.column});
    out_.poly.push_back(std::move(w));
    has_words_ = true;
  }

  // RET(target, continue after it, levels, to the start) (Job Planning, "Parameterizable
  // subprogram return jump"): every argument may be left out.
  void parameterised_return(const Item& item) {
    if (item.arg_count > 4) throw LineError(12340, item.column, "RET takes at most 4 parameters");
    auto arg = [&](uint32_t k) -> std::optional<Value> {
      if (k >= item.arg_count) return std::nullopt;
      const ExprIndex a = l_.parsed_.pool.args[item.arg_first + k];
      if (a == kNoExpr) return std::nullopt;
      return l_.eval_value(a);
    };
    ProgramLoader::ReturnRequest r;
    if (auto t = arg(0)) r.target = *t;
    if (auto a = arg(1)) r.after_target = as_number(*a, item.column) != 0;
    if (auto n = arg(2)) {
      const double levels = as_number(*n, item.column);
      if (!(levels >= 1 && levels <= 11) || levels != std::floor(levels))
        throw LineError(12160, item.column, "RET: return levels must be 1..11");
      r.levels = static_cast<int>(levels);
    }
    if (auto s = arg(3)) r.to_start = as_number(*s, item.column) != 0;
    l_.return_request_ = r;
    add_command(item);
    action_ = PendingAction::Return;
  }

  // "OVR=", "FXS[Z]= (travel to fixed stop: ...)": what a warned setting names.
  std::string not_modelled_assignment(const Item& item) {
    std::string text(item.name);
    if (item.index_count == 1) {
      const Value index = l_.eval_value(l_.parsed_.pool.args[item.index_first]);
      text += "[" + (index.is_number() ? number_to_text(index.number) : index.text) + "]";
    }
    text += "=";
    if (item.name == "FXS" || item.name == "FXST" || item.name == "FXSW")
      text += " (travel to fixed stop: the axis is planned to the programmed end point)";
    return text;
  }

  // The axis of NAME[axis] (AXNAME("X") and axis variables too), upper case.
  std::string axis_index_text(const Item& item) {
    if (item.index_count != 1) throw LineError(12410, item.column, std::string(item.name) + "[...] takes one axis");
    const Value index = l_.eval_value(l_.parsed_.pool.args[item.index_first]);
    if (index.kind != ValueKind::Axis && !index.is_text()) throw LineError(12150, item.column, std::string(item.name) + "[...] needs an axis");
    std::string axis = index.text;
    for (char& c : axis) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return axis;
  }

  // MCALL name(args): the loader calls it after every later block with axis motion
  // (ProgramLoader::next); the arguments are values taken now.
  void set_modal_call() {
    if (call_name_.empty()) {
      l_.modal_call_.reset();
      return;
    }
    if (passes_ != 1) throw LineError(12080, call_column_, "MCALL with passes P");
    ModalCall call{call_name_, std::move(call_args_), call_column_};
    for (CallArgument& a : call.args) {  // values only: the variables may be gone when it runs
      if (a.element == SIZE_MAX) a.given = false;
      a.variable = nullptr;
      a.r_parameter = nullptr;
    }
    l_.modal_call_ = std::move(call);
    call_name_.clear();
    call_args_.clear();
  }

  void set_call(std::string_view name, uint32_t column) {
    if (!call_name_.empty()) throw LineError(12080, column, "two program calls in one block");
    call_name_.assign(name);
    call_column_ = column;
  }

  bool finish() {
    f_.executed_block = f_.executed_block || has_words_ || !call_name_.empty();
    if (mcall_) set_modal_call();
    if (!call_name_.empty()) {
      // A misspelled command next to other words is not a call: say what it probably is.
      if (has_words_) {
        const std::string_view guess = near_miss(call_name_);
        if (!guess.empty())
          throw LineError(12550, call_column_, "name " + call_name_ + " not defined (did you mean " + std::string(guess) + "?)");
      }
      l_.pending_ = PendingAction::Call;
      l_.pending_call_ = call_name_;
      l_.pending_passes_ = passes_;
      l_.pending_column_ = call_column_;
      l_.pending_args_ = std::move(call_args_);
      l_.pending_section_program_ = std::move(section_program_);
      l_.pending_section_start_ = std::move(section_start_);
      l_.pending_section_end_ = std::move(section_end_);
    }
    if (action_ != PendingAction::None) {
      if (l_.pending_ == PendingAction::Call) throw LineError(12080, call_column_, "program call and program end in one block");
      l_.pending_ = action_;
    }
    if (!has_words_) return false;
    if (out_.file != f_.file) out_.file = f_.file;
    out_.line = l_.position_.line;
    out_.text.assign(trimmed(l_.text_));
    out_.number = l_.parsed_.number;
    out_.program_level = static_cast<int>(l_.frames_.size()) - 1;
    // A main-run variable read on this line or a line consumed since the last block (an IF, an
    // assignment): the block preparation waited there.
    const uint64_t reads = l_.system_variables_.main_run_reads();
    out_.main_run_read = reads != l_.main_run_reads_seen_;
    l_.main_run_reads_seen_ = reads;
    ++l_.blocks_executed_;
    return true;
  }

  static bool is_r_parameter_name(std::string_view n) {
    return n.size() >= 2 && n[0] == 'R' &&
           std::all_of(n.begin() + 1, n.end(), [](char c) { return c >= '0' && c <= '9'; });
  }

  ProgramLoader& l_;
  Block& out_;
  Frame& f_;
  std::string call_name_;
  std::string section_program_, section_start_, section_end_;  // DRYCUT_CONTOUR_CALL("PROG:START:END")
  uint32_t call_column_ = 0;
  uint64_t passes_ = 1;
  bool mcall_ = false;
  bool has_words_ = false;
  PendingAction action_ = PendingAction::None;
  std::vector<CallArgument> call_args_;
};

bool ProgramLoader::execute_words(Block& out) { return BlockBuilder(*this, out).build(); }

}  // namespace drycut::parser
