// Names in the loader: user variables (local LUD, then global GUD), R parameters, `$` system
// variables through the registry, TRUE/FALSE, and bare axis names (AXIS values: X, Y1, AX3).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "parser/ascii_case.hpp"
#include "parser/line_error.hpp"
#include "parser/loader_frame.hpp"
#include "parser/program_files.hpp"
#include "parser/stringis.hpp"

namespace drycut::parser {

namespace {

constexpr size_t kRParameterCount = 1000;

bool all_digits(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A STRING scalar with one index, NAME[i], is its character at position i counted from 0
// (PGA Job Planning, "Read and write individual characters"); i must lie inside the text.
bool is_character_access(const Variable& v, size_t index_count) {
  return v.type() == DataType::String && v.rank() == 0 && index_count == 1;
}

size_t character_position(const std::string& text, const Value& index, uint32_t column) {
  if (!index.is_number()) throw LineError(12150, column, "a character index must be a number");
  const double i = index_from_real(index.number);
  if (!(i >= 0 && i < static_cast<double>(text.size())))
    throw LineError(17020, column, "character index " + number_to_text(i) + " outside the string");
  return static_cast<size_t>(i);
}

// SPI(n) (Job Planning, "SPI"): the axis name of spindle n; drycut names spindles SP<n>.
Value spi_value(const ExprNode& call, std::span<const Value> args) {
  if (args.empty() || !args[0].is_number() || args[0].number < 1 ||
      args[0].number != std::trunc(args[0].number))
    throw LineError(12150, call.column, "SPI needs a spindle number 1, 2 ...");
  return Value::of_axis("SP" + std::to_string(static_cast<int64_t>(args[0].number)));
}

// A frame function: the FRAME value carries its own text, "CTRANS(X,10,Y,5)", which the
// interpreter computes where the frame is written ($P_UIFR, $P_PFRAME; frame_components.hpp).
Value frame_function_value(const ExprNode& call, std::span<const Value> args) {
  std::string text(call.text);
  text += '(';
  char buf[32];
  for (size_t k = 0; k < args.size(); ++k) {
    if (k > 0) text += ',';
    if (args[k].is_number()) {
      std::snprintf(buf, sizeof buf, "%.17g", args[k].number);
      text += buf;
    } else {
      text += args[k].text;
    }
  }
  text += ')';
  Value v = Value::of_frame();
  v.text = std::move(text);
  return v;
}

}  // namespace

Variable* ProgramLoader::find_variable(std::string_view name) {
  if (!frames_.empty()) {
    if (Variable* v = frames_.back()->locals.find(name)) return v;
    // MD11120 LUD_EXTENDED_SCOPE = 1: the main program's variables (PUD) are seen in its
    // subprograms too.
    if (program_global_data_ && frames_.size() > 1)
      if (Variable* v = frames_.front()->locals.find(name)) return v;
  }
  return globals_.find(name);
}

bool ProgramLoader::is_axis_name(std::string_view name) const {
  // Geometry and special axes by letter, numbered machine axes (X1, A2), AX<n> channel axes,
  // SP<n> spindles, and the machine's own names from the profile.
  if (name.empty()) return false;
  if (std::string_view("XYZABCUVW").find(name[0]) != std::string_view::npos && all_digits(name.substr(1)))
    return true;
  if ((name.substr(0, 2) == "AX" || name.substr(0, 2) == "SP") && name.size() > 2 && all_digits(name.substr(2)))
    return true;
  return std::find(options_.axis_names.begin(), options_.axis_names.end(), name) != options_.axis_names.end();
}

Value ProgramLoader::Scope::variable(std::string_view name, std::span<const Value> indices, uint32_t column) const {
  ProgramLoader& l = loader_;
  if (!name.empty() && name[0] == '$') {
    if (auto v = l.program_variable(name, indices)) return *v;
    const auto r = l.system_variables_.read(name, indices);
    if (r.assumed)
      l.warn(990007, std::string(system_variable_class_name(classify_system_variable(name))) + " " +
                         system_variable_key(name, indices) + " not in the machine profile: 0 assumed",
             column);
    return r.value;
  }
  if (const Variable* v = l.find_variable(name)) {
    if (v->stop_on_read) l.system_variables_.note_preprocessing_stop();
    if (!l.sync_written_names_.empty() && l.sync_written_names_.count(name))
      l.system_variables_.note_external_read(std::string(name) + " (written by a synchronized action)");
    if (is_character_access(*v, indices.size())) {
      const std::string text = v->get(v->element({}, column)).text;
      return Value::of_text(std::string(1, text[character_position(text, indices[0], column)]));
    }
    if (v->type() == DataType::Frame && v->rank() == 0 && indices.size() == 2) {
      // A component of a FRAME variable (_FR[X,TR]): the loader keeps frames as the text of
      // their functions; the interpreter computes the component (docs/controller-state.md, Frames).
      if (l.state_view_)
        if (const auto c = l.state_view_->frame_component(v->get(0).text, indices[0].text, indices[1].text))
          return Value(*c);
      l.warn(990007, std::string(name) + "[axis, component] of a FRAME variable is not computed: 0 assumed", column);
      return Value(0.0);
    }
    return v->get(v->element(indices, column));
  }
  if (indices.empty()) {
    if (name == "TRUE") return Value(1.0);
    if (name == "FALSE") return Value(0.0);
    // Frame components as indices of frame variables: $P_UIFR[1, X, TR] (PGA "Frame components").
    if (name == "TR" || name == "FI" || name == "RT" || name == "SC" || name == "MI") return Value::of_text(std::string(name));
    if (l.is_axis_name(name)) return Value::of_axis(std::string(name));
    // S<n> names spindle n as an index of system variables ($AA_S[S1], $AA_COUP_ACT[S2]: Job
    // Planning, "Coupled motion"; Function Manual S3): the same axis as SPI(n), SP<n>.
    if (name.size() > 1 && name[0] == 'S' && name[1] != '0' && all_digits(name.substr(1)))
      return Value::of_axis("SP" + std::string(name.substr(1)));
  }
  throw LineError(12550, column, "name " + std::string(name) + " not defined");
}

// $R[n] / $Rn: the R parameter n, the form synchronized actions use (Job Planning, "R
// parameters"); the same storage as Rn. Returns n, or none for another name.
static std::optional<double> r_parameter_index(std::string_view name, std::span<const Value> indices) {
  if (name == "$R" && indices.size() == 1 && indices[0].is_number()) return indices[0].number;
  if (name.size() > 2 && name.substr(0, 2) == "$R" && indices.empty() &&
      std::all_of(name.begin() + 2, name.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::stod(std::string(name.substr(2)));
  return std::nullopt;
}

// A synchronized action's targets (ParsedLine::sync_targets): $Rn, $R[n] and Rn are R parameter
// n; other $ names go to the system variables; the rest are user variables (GUD with SYNRW),
// by name (an index does not narrow them).
void ProgramLoader::note_sync_action_targets() {
  for (const std::string& t : parsed_.sync_targets) {
    const size_t bracket = t.find('[');
    const std::string_view name = std::string_view(t).substr(0, bracket);
    // Rn (the program's spelling) is read as $Rn; a literal index is the key's first number.
    const std::string dollar_name = name.size() > 1 && name[0] == 'R' && all_digits(name.substr(1)) ? "$" + std::string(name)
                                                                                                     : std::string(name);
    const Value index(bracket != std::string::npos ? std::stod(t.substr(bracket + 1)) : 0.0);
    const std::span<const Value> indices(&index, bracket != std::string::npos ? 1 : 0);
    if (const auto r = r_parameter_index(dollar_name, indices)) {
      sync_written_r_.insert(*r);
    } else if (dollar_name == "$R") {
      sync_actions_writes_all_r_ = true;  // $R[computed index]
    } else if (name.starts_with("$")) {
      system_variables_.note_sync_action_target(t);
    } else {
      sync_written_names_.emplace(name);
    }
  }
}

std::optional<Value> ProgramLoader::program_variable(std::string_view name, std::span<const Value> indices) const {
  if (const auto r = r_parameter_index(name, indices)) {
    // $Rn is the form synchronized actions write: after one was programmed, a loop polling it waits.
    if (sync_actions_seen_) system_variables_.note_external_read("$R" + number_to_text(*r) + " (written by a synchronized action)");
    return Value(scope_->r_parameter(*r, 0));
  }
  if (frames_.empty()) return std::nullopt;
  const Frame& f = *frames_.back();
  // $P_SUBPAR[n]: was parameter n (from 1) given in the call of this program (Job Planning,
  // "$P_SUBPAR"); a parameter beyond the arguments written is not.
  if (name == "$P_SUBPAR" && indices.size() == 1 && indices[0].is_number()) {
    const double n = indices[0].number;
    const bool given = n >= 1 && n <= static_cast<double>(f.args.size()) && f.args[static_cast<size_t>(n) - 1].given;
    return Value(given ? 1.0 : 0.0);
  }
  // $P_STACK: the program level of the block being prepared, 0 in the main program (Job
  // Planning, system variables "$P_STACK"); a cycle tests it to know whether it was called.
  if (name == "$P_STACK") return Value(static_cast<double>(frames_.size()) - 1);
  // $P_PROG / $P_PROGPATH: the running program's name and its path in the control's notation
  // (/_N_MPF_DIR/_N_NAME_MPF; subprograms in _N_SPF_DIR), drycut's rendering of a file it
  // read from a folder (inferred).
  // $P_PROG[n]: the name of the program running at level n (0 the main program).
  if (name == "$P_PROG" && indices.size() == 1 && indices[0].is_number()) {
    const double n = indices[0].number;
    if (n >= 0 && n < static_cast<double>(frames_.size()) && n == std::trunc(n))
      return Value::of_text(frames_[static_cast<size_t>(n)]->program);
    throw LineError(17020, 0, "$P_PROG[" + as_text(indices[0]) + "]: no program at that level");
  }
  if (name == "$P_PROG" || name == "$P_PROGPATH") {
    const bool main = frames_.size() == 1;
    const char* type = main ? "MPF" : "SPF";
    std::string path = std::string("/_N_") + type + "_DIR/_N_" + f.program + "_" + type;
    return Value::of_text(name == "$P_PROG" ? f.program : std::move(path));
  }
  return std::nullopt;
}

double ProgramLoader::Scope::r_parameter(double real_index, uint32_t column) const {
  const double index = index_from_real(real_index);
  if (!(index >= 0 && index < static_cast<double>(kRParameterCount)))
    throw LineError(12430, column, "R parameter index must be 0..999");
  if (loader_.sync_actions_writes_all_r_ || (!loader_.sync_written_r_.empty() && loader_.sync_written_r_.count(index)))
    loader_.system_variables_.note_external_read("R" + number_to_text(index) + " (written by a synchronized action)");
  return loader_.r_parameters_[static_cast<size_t>(index)];
}

Value ProgramLoader::Scope::environment_function(const ExprNode& call, std::span<const Value> args) const {
  switch (call.func) {
    case Function::IsVar: return isvar_value(call, args);
    case Function::IsFile: return isfile_value(call, args);
    case Function::StringIs: return stringis_value(call, args);
    case Function::Spindle: return spi_value(call, args);
    case Function::NameToInt: return nametoint_value(call, args);
    case Function::GetT: return gett_value(call, args);
    default: return frame_function_value(call, args);
  }
}

Value ProgramLoader::Scope::isvar_value(const ExprNode& call, std::span<const Value> args) const {
  // Job Planning, "Check existence of a variable (ISVAR)": TRUE when the name is a variable the
  // control knows and, written with an index, the index lies within the array.
  ProgramLoader& l = loader_;
  if (args.empty() || args[0].is_number())
    throw LineError(12150, call.column, "ISVAR needs a name as a string");
  std::string name = upper_ascii(args[0].text);
  std::string index_text;
  if (const size_t b = name.find('['); b != std::string::npos) {
    const size_t e = name.find(']', b);
    index_text = name.substr(b + 1, e == std::string::npos ? std::string::npos : e - b - 1);
    name.resize(b);
  }
  if (const Variable* v = l.find_variable(name)) return Value(index_within(*v, index_text) ? 1.0 : 0.0);
  if (name.size() > 1 && name[0] == 'R' && all_digits(name.substr(1))) return Value(1.0);
  if (name.empty() || name[0] != '$' || !l.system_variables_.is_known(name)) return Value(0.0);
  const SystemVariableClass c = classify_system_variable(name);
  if (c == SystemVariableClass::MachineData || c == SystemVariableClass::SettingData) {
    // Machine and setting data the profile gives are known; others may exist on the machine
    // the program was written for (options, software versions): TRUE, with a warning.
    if (!l.system_variables_.profile_gives(name)) l.warn(990007, "ISVAR(\"" + name + "\"): " + std::string(system_variable_class_name(c)) +
                                   " not in the machine profile: TRUE assumed", call.column);
  }
  return Value(1.0);
}

// An ISVAR index ("3", "1,2"): as many whole numbers as the array has dimensions, each below
// its size; no index at all names the variable itself.
bool ProgramLoader::Scope::index_within(const Variable& v, std::string_view text) {
  if (text.empty()) return true;
  int k = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    const size_t comma = std::min(text.find(',', pos), text.size());
    std::string_view part = text.substr(pos, comma - pos);
    while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
    while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
    if (k >= v.rank() || part.empty() || !all_digits(part)) return false;
    if (part.size() > 9 || std::stoul(std::string(part)) >= v.dim(k)) return false;
    ++k;
    pos = comma + 1;
  }
  return k == v.rank();
}

Value ProgramLoader::Scope::isfile_value(const ExprNode& call, std::span<const Value> args) const {
  // Job Planning, "File functions": TRUE when the file exists in the NCK's file system.
  // drycut's file system is its folders (main program, search path, standard cycles).
  if (args.empty() || args[0].is_number())
    throw LineError(12150, call.column, "ISFILE needs a file name as a string");
  return Value(loader_.files_->find(normalize_program_name(args[0].text)) ? 1.0 : 0.0);
}

Value ProgramLoader::Scope::stringis_value(const ExprNode& call, std::span<const Value> args) const {
  ProgramLoader& l = loader_;
  if (args.empty() || args[0].is_number())
    throw LineError(12150, call.column, "STRINGIS needs a name as a string");
  const std::string name = upper_ascii(args[0].text);
  StringIsContext context;
  context.is_macro = [&](std::string_view n) { return l.macros_.count(std::string(n)) > 0; };
  context.is_local_variable = [&](std::string_view n) { return l.frames_.back()->locals.find(n) != nullptr; };
  context.is_global_variable = [&](std::string_view n) { return l.globals_.find(n) != nullptr; };
  context.is_program_file = [&](std::string_view n) {
    return l.files_->find(normalize_program_name(std::string(n))).has_value();
  };
  return Value(static_cast<double>(stringis_code(name, context)));
}

Value ProgramLoader::Scope::nametoint_value(const ExprNode& call, std::span<const Value> args) const {
  // NAMETOINT(array name, name[, no alarm]): the index of `name` among the STRING elements of
  // a system array such as $MC_AXCONF_CHANAX_NAME_TAB, counted from 0 like the array's own
  // index (inferred: no manual at hand states the base). Not found: alarm 12550, or -1 when
  // the third argument is TRUE.
  if (args.size() < 2 || args[0].is_number() || args[1].is_number())
    throw LineError(12150, call.column, "NAMETOINT needs an array name and a name as strings");
  const std::string array = upper_ascii(args[0].text), wanted = upper_ascii(args[1].text);
  for (int i = 0; i < 64; ++i) {
    const Value index(static_cast<double>(i));
    const auto r = loader_.system_variables_.read(array, std::span<const Value>(&index, 1));
    if (r.assumed) break;
    if (!r.value.is_number() && upper_ascii(r.value.text) == wanted) return Value(static_cast<double>(i));
  }
  if (args.size() > 2 && args[2].is_number() && args[2].number != 0) return Value(-1.0);
  throw LineError(12550, call.column, "NAMETOINT: " + wanted + " is not in " + array);
}

Value ProgramLoader::Scope::gett_value(const ExprNode& call, std::span<const Value> args) const {
  // GETT(name[, duplo]) (Function Manual Tool Management, "GETT"): the T number of the name's
  // sister tool with that duplo number, -1 when there is none.
  if (args.empty() || args[0].is_number()) throw LineError(12150, call.column, "GETT needs a tool name");
  if (args.size() > 1 && !args[1].is_number()) throw LineError(12150, call.column, "GETT: the duplo number must be a number");
  const Value key[2] = {Value::of_text(args[0].text), args.size() > 1 ? args[1] : Value(0.0)};
  const auto r = loader_.system_variables_.read("$TC_GETT", std::span<const Value>(key, args.size() > 1 ? 2 : 1));
  if (r.assumed)
    loader_.warn(990007, "GETT(\"" + args[0].text + "\"): tool table not available, -1 assumed", call.column);
  return r.assumed ? Value(-1.0) : r.value;
}

void ProgramLoader::assign_variable(Variable& v, uint32_t index_first, uint32_t index_count, ExprIndex value,
                                    uint32_t column) {
  if (v.stop_on_write) system_variables_.note_preprocessing_stop();
  Value idx[3];
  for (uint32_t k = 0; k < index_count && k < 3; ++k) idx[k] = eval_value(parsed_.pool.args[index_first + k]);
  if (is_character_access(v, index_count)) {  // NAME[i]="C": one character of a STRING
    const size_t e = v.element({}, column);
    std::string text = v.get(e).text;
    const Value c = eval_value(value);
    if (c.is_text() && c.text.size() != 1) throw LineError(12150, column, "one character expected");
    if (!c.is_text() && !c.is_number()) throw LineError(12150, column, "one character expected");
    const size_t at = character_position(text, idx[0], column);
    text[at] = c.is_text() ? c.text[0] : static_cast<char>(c.number);
    // The 0 character ends a string (Job Planning, "String operations": a character replaced by
    // 0 truncates the string there).
    if (text[at] == '\0') text.resize(at);
    v.set(e, Value::of_text(text), column);
    return;
  }
  if (v.type() == DataType::Frame && v.rank() == 0 && index_count == 2) {
    // _FR[X,TR]=v: the frame with that component set (Job Planning, "Frame components").
    const std::optional<std::string> text =
        state_view_ ? state_view_->frame_with_component(v.get(0).text, idx[0].text, idx[1].text,
                                                        as_number(eval_value(value), column))
                    : std::nullopt;
    if (!text) {
      warn(990007, v.name() + "[axis, component] of a FRAME variable not written (drycut cannot split this frame)", column);
      return;
    }
    Value frame = Value::of_frame();
    frame.text = *text;
    v.set(0, frame, column);
    return;
  }
  const size_t e = v.element(std::span<const Value>(idx, index_count), column);
  const ExprNode& n = parsed_.pool[value];
  if (n.op == ExprOp::Call && n.func == Function::ArraySet) {  // consecutive elements from e
    if (e + n.b > v.size()) throw LineError(17020, column, "SET writes past the end of " + v.name());
    for (uint32_t k = 0; k < n.b; ++k) v.set(e + k, within_limits(v, eval_value(parsed_.pool.args[n.a + k]), column), column);
    return;
  }
  if (n.op == ExprOp::Call && n.func == Function::ArrayRep) {  // element e and all after it
    const Value x = within_limits(v, eval_value(parsed_.pool.args[n.a]), column);
    for (size_t k = e; k < v.size(); ++k) v.set(k, x, column);
    return;
  }
  v.set(e, within_limits(v, eval_value(value), column), column);
}

const Value& ProgramLoader::within_limits(const Variable& v, const Value& x, uint32_t column) {
  // DEF ... LLI/ULI (Job Planning, "Attribute: Limit values (LLI, ULI)"): the control refuses a
  // write outside them with an alarm whose number drycut does not know, so it warns, writes the
  // value and goes on (a warning, never a false alarm).
  if (x.is_number() && (x.number < v.lower_limit || x.number > v.upper_limit))
    warn(990002, v.name() + "=" + number_to_text(x.number) + " outside its limits LLI " + number_to_text(v.lower_limit) +
                     " .. ULI " + number_to_text(v.upper_limit) + " (the control refuses the write; drycut writes it)",
         column);
  return x;
}

void ProgramLoader::assign_r_parameter(double real_index, double value, uint32_t column) {
  scope_->r_parameter(real_index, column);  // range check
  const double index = index_from_real(real_index);
  r_parameters_[static_cast<size_t>(index)] = value;
  r_used_ = std::max(r_used_, static_cast<size_t>(index) + 1);
}

void ProgramLoader::assign_system_variable(const Item& item, Block& out) {
  Value idx[3];
  for (uint32_t k = 0; k < item.index_count && k < 3; ++k) idx[k] = eval_value(parsed_.pool.args[item.index_first + k]);
  const std::span<const Value> indices(idx, item.index_count);
  const Value v = eval_value(item.expr);
  if (const auto r = r_parameter_index(item.name, indices)) {
    assign_r_parameter(*r, as_number(v, item.column), item.column);
    return;
  }
  if (classify_system_variable(item.name) == SystemVariableClass::Unknown)
    warn(990002, "system variable " + std::string(item.name) + " written (not modelled)", item.column);
  system_variables_.write(item.name, indices, v);
  SystemWrite& w = out.system_writes.emplace_back();
  w.name.assign(item.name);
  w.indices.assign(indices.begin(), indices.end());
  w.value = v;
  w.column = item.column;
}

CallArgument ProgramLoader::call_argument(ExprIndex e) {
  CallArgument a;
  if (e == kNoExpr) return a;  // an empty argument: the parameter keeps its default
  a.given = true;
  const ExprNode& n = parsed_.pool[e];
  if (n.op == ExprOp::RParam || n.op == ExprOp::RParamIndex) {
    const double index = n.op == ExprOp::RParam ? n.value : eval(n.a);
    scope_->r_parameter(index, n.column);
    a.r_parameter = &r_parameters_[static_cast<size_t>(index)];
    r_used_ = std::max(r_used_, static_cast<size_t>(index) + 1);  // a VAR parameter may write it
    a.value = Value(*a.r_parameter);
    return a;
  }
  if (n.op == ExprOp::Name && (n.text.empty() || n.text[0] != '$')) {
    Variable* v = find_variable(n.text);
    // More indexes than the variable has dimensions: a frame component (_FR[X,TR]) or a string
    // character (_S[1]) — a value, not an element a VAR parameter could refer to.
    if (v && n.b > static_cast<uint32_t>(v->rank())) v = nullptr;
    if (v) {
      a.variable = v;
      if (n.b == 0 && v->rank() > 0) {  // a whole array (VAR parameter)
        a.element = SIZE_MAX;
        return a;
      }
      Value idx[3];
      for (uint32_t k = 0; k < n.b && k < 3; ++k) idx[k] = eval_value(parsed_.pool.args[n.a + k]);
      a.element = v->element(std::span<const Value>(idx, n.b), n.column);
      a.value = v->get(a.element);
      return a;
    }
  }
  a.value = eval_value(e);
  return a;
}

}  // namespace drycut::parser
