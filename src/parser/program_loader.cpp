#include "parser/program_loader.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "parser/command_table.hpp"
#include "parser/expression_evaluator.hpp"
#include "parser/expression_parser.hpp"
#include "parser/line_error.hpp"
#include "parser/text_decoding.hpp"

namespace drycut::parser {

namespace {

constexpr size_t kMaxCachedLabels = 100000;
constexpr size_t kMaxWarnings = 10000;
constexpr size_t kRParameterCount = 1000;  // R0 .. R999

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool is_opener(Statement s) {
  return s == Statement::If || s == Statement::While || s == Statement::For ||
         s == Statement::Repeat || s == Statement::Loop;
}
bool is_closer(Statement s) {
  return s == Statement::EndIf || s == Statement::EndWhile || s == Statement::EndFor ||
         s == Statement::Until || s == Statement::EndLoop;
}
Statement closer_of(Statement opener) {
  switch (opener) {
    case Statement::If: return Statement::EndIf;
    case Statement::While: return Statement::EndWhile;
    case Statement::For: return Statement::EndFor;
    case Statement::Repeat: return Statement::Until;
    default: return Statement::EndLoop;
  }
}
const char* keyword(Statement s) {
  switch (s) {
    case Statement::If: return "IF";
    case Statement::Else: return "ELSE";
    case Statement::EndIf: return "ENDIF";
    case Statement::While: return "WHILE";
    case Statement::EndWhile: return "ENDWHILE";
    case Statement::For: return "FOR";
    case Statement::EndFor: return "ENDFOR";
    case Statement::Repeat: return "REPEAT";
    case Statement::Until: return "UNTIL";
    case Statement::Loop: return "LOOP";
    case Statement::EndLoop: return "ENDLOOP";
    default: return "?";
  }
}

}  // namespace

struct ProgramLoader::ControlFrame {
  Statement kind = Statement::If;
  LinePosition head;  // the opening line
  LinePosition body;  // the line after it
  double end = 0.0;   // FOR: last value
  std::string variable;  // FOR: loop variable
};

struct Variable {
  std::string name;
  std::string type;  // INT REAL BOOL CHAR STRING AXIS FRAME
  double number = 0.0;
  std::string text;
  uint32_t def_line = 0;
};

struct ProgramLoader::Frame {
  std::shared_ptr<const std::string> file;  // as shown in alarms
  std::string program;                      // upper-case program name
  LineReader reader;
  uint64_t passes_left = 1;
  std::vector<double> args;  // call arguments, bound by PROC
  std::vector<ControlFrame> control;
  std::unordered_map<std::string, LinePosition> labels;  // labels passed so far
  std::vector<Variable> locals;
  bool executed_block = false;  // DEF is only allowed before the first executed block

  Variable* find_local(std::string_view name) {
    for (auto& v : locals)
      if (v.name == name) return &v;
    return nullptr;
  }
};

// Values of names for the expression evaluator: R parameters and the current program's
// DEF variables.
class ProgramLoader::Scope : public VariableSource {
 public:
  explicit Scope(ProgramLoader& loader) : loader_(loader) {}
  double variable(std::string_view name, uint32_t column) const override {
    if (!loader_.frames_.empty())
      if (const Variable* v = loader_.frames_.back()->find_local(name)) {
        if (v->type == "STRING") throw LineError(12150, column, "STRING variable " + v->name + " in a numeric expression");
        return v->number;
      }
    if (name == "TRUE") return 1.0;
    if (name == "FALSE") return 0.0;
    throw LineError(12550, column, "name " + std::string(name) + " not defined");
  }
  double r_parameter(double index, uint32_t column) const override {
    if (index < 0 || index >= static_cast<double>(kRParameterCount) || index != std::trunc(index))
      throw LineError(12430, column, "R parameter index must be 0..999");
    return loader_.r_parameters_[static_cast<size_t>(index)];
  }

 private:
  ProgramLoader& loader_;
};

ProgramLoader::ProgramLoader(LoaderOptions options, Diagnostics& diagnostics)
    : options_(std::move(options)),
      diagnostics_(diagnostics),
      scope_(std::make_unique<Scope>(*this)),
      r_parameters_(kRParameterCount, 0.0) {}

ProgramLoader::~ProgramLoader() = default;

void ProgramLoader::open_main(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw UsageError("cannot read program '" + path.string() + "': no such file");
  auto frame = std::make_unique<Frame>();
  if (!frame->reader.open(path)) throw UsageError("cannot open program '" + path.string() + "'");
  frame->file = std::make_shared<const std::string>(path.string());
  frame->program = normalize_program_name(path.stem().string() + path.extension().string()).name;
  std::vector<std::filesystem::path> dirs;
  dirs.push_back(path.has_parent_path() ? path.parent_path() : std::filesystem::path("."));
  for (const auto& d : options_.search_path) dirs.push_back(d);
  files_ = std::make_unique<ProgramFiles>(std::move(dirs));
  programs_used_.push_back(frame->program);
  frames_.clear();
  frames_.push_back(std::move(frame));
}

void ProgramLoader::raise(int number, const std::string& detail, uint32_t column) const {
  SourceLocation where;
  if (!frames_.empty()) where.file = *frames_.back()->file;
  where.line = position_.line;
  where.column = column;
  throw AlarmError(make_alarm(number, detail, std::move(where), std::string(trimmed(text_))));
}

double ProgramLoader::eval(ExprIndex e) const {
  const double v = evaluate(parsed_.pool, e, *scope_);
  if (!std::isfinite(v)) raise(14051, "result is not a finite number", parsed_.pool[e].column);
  return v;
}

std::vector<std::string> ProgramLoader::commands_used() const {
  std::vector<std::string> out;
  for (size_t i = 0; i < g_used_.size(); ++i)
    if (g_used_[i]) out.push_back("G" + std::to_string(i));
  for (size_t i = 0; i < m_used_.size(); ++i)
    if (m_used_[i]) out.push_back("M" + std::to_string(i));
  out.insert(out.end(), commands_used_.begin(), commands_used_.end());
  std::sort(out.begin(), out.end());
  return out;
}

bool ProgramLoader::read_line(Frame& f) {
  if (!f.reader.next(raw_)) {
    if (f.reader.read_error()) raise(990005, "read error in " + *f.file, 0);
    return false;
  }
  position_ = raw_.position;
  if (++steps_ > options_.max_steps) {
    text_.clear();
    raise(990004, "more than " + std::to_string(options_.max_steps) + " lines executed", 0);
  }
  if (raw_.too_long) {
    text_.clear();
    raise(12080, "block longer than " + std::to_string(LineReader::kMaxLineLength) + " characters", 1);
  }
  std::string_view bytes = raw_.bytes;
  if (position_.line == 1 && bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);  // BOM
  if (is_ascii(bytes))
    text_.assign(bytes);
  else
    decode_line_to_utf8(bytes, text_);
  return true;
}

bool ProgramLoader::next(Block& out) {
  for (;;) {
    switch (pending_) {
      case PendingAction::None: break;
      case PendingAction::Call:
        pending_ = PendingAction::None;
        call_program(pending_call_, pending_passes_, pending_column_);
        break;
      case PendingAction::Return:
        pending_ = PendingAction::None;
        finish_frame();
        break;
      case PendingAction::EndProgram:
        pending_ = PendingAction::None;
        frames_.clear();
        break;
    }
    if (frames_.empty()) return false;
    Frame& f = *frames_.back();
    if (!read_line(f)) {
      end_of_file();
      continue;
    }
    const std::string_view t = trimmed(text_);
    if (t.empty() || t.front() == ';' || t.front() == '%') continue;  // empty, comment, tape header
    if (frames_.size() == 1) main_has_content_ = true;
    if (execute_line(out)) return true;
  }
}

bool ProgramLoader::execute_line(Block& out) {
  try {
    parser_.parse(text_, parsed_);
  } catch (const LineError& e) {
    raise(e.number(), e.detail(), e.column());
  }
  if (parsed_.skip_level >= 0 && options_.skip_levels_active[static_cast<size_t>(parsed_.skip_level)])
    return false;
  Frame& f = *frames_.back();
  if (!parsed_.label.empty() && f.labels.size() < kMaxCachedLabels)
    f.labels.insert_or_assign(std::string(parsed_.label), position_);
  try {
    switch (parsed_.statement) {
      case Statement::Words: return execute_words(out);
      case Statement::Def: execute_def(); return false;
      case Statement::Proc: execute_proc(); return false;
      case Statement::Call: {
        uint64_t passes = 1;
        if (!parsed_.items.empty()) passes = static_cast<uint64_t>(parsed_.items.front().code);
        f.executed_block = true;
        call_program(std::string(parsed_.call_name), passes, parsed_.target.column);
        return false;
      }
      case Statement::Goto:
        f.executed_block = true;
        jump(parsed_.jump, std::string(parsed_.target.label), parsed_.target.number, parsed_.target.column);
        return false;
      case Statement::IfGoto:
        f.executed_block = true;
        if (eval(parsed_.condition) != 0.0)
          jump(parsed_.jump, std::string(parsed_.target.label), parsed_.target.number, parsed_.target.column);
        return false;
      default:
        f.executed_block = true;
        execute_control();
        return false;
    }
  } catch (const LineError& e) {
    raise(e.number(), e.detail(), e.column());
  }
}

void ProgramLoader::warn_not_modelled(std::string_view name, uint32_t column) {
  if (warned_.size() >= kMaxWarnings) return;
  // One warning per command and line: a loop must not print it a million times.
  std::string key = std::string(name) + '@' + *frames_.back()->file + ':' + std::to_string(position_.line);
  if (!warned_.insert(std::move(key)).second) return;
  diagnostics_.warn(990002, std::string(name), SourceLocation{*frames_.back()->file, position_.line, column},
                    std::string(trimmed(text_)));
}

void ProgramLoader::assign(const Item& item) {
  const double value = eval(item.expr);
  if (item.index != kNoExpr) {
    const double index = eval(item.index);
    scope_->r_parameter(index, item.column);  // range check
    r_parameters_[static_cast<size_t>(index)] = value;
    return;
  }
  if (item.name.size() >= 2 && item.name[0] == 'R' &&
      std::all_of(item.name.begin() + 1, item.name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    const double index = std::stod(std::string(item.name.substr(1)));
    scope_->r_parameter(index, item.column);
    r_parameters_[static_cast<size_t>(index)] = value;
    return;
  }
  Variable* v = frames_.back()->find_local(item.name);
  if (!v) throw LineError(12550, item.column, "name " + std::string(item.name) + " not defined");
  if (v->type == "INT") v->number = std::round(value);
  else if (v->type == "BOOL") v->number = value != 0.0 ? 1.0 : 0.0;
  else v->number = value;
}

bool ProgramLoader::execute_words(Block& out) {
  Frame& f = *frames_.back();
  out.clear();
  std::string call_name;
  uint32_t call_column = 0;
  uint64_t passes = 1;
  bool has_words = false;
  PendingAction action = PendingAction::None;
  pending_args_.clear();
  // A modelled command (ASPLINE, SOFT, CYCLE832(...)) goes into the block and the statistics.
  auto add_command = [&](const Item& item) -> CommandWord& {
    if (commands_used_.find(item.name) == commands_used_.end()) commands_used_.emplace(item.name);
    has_words = true;
    CommandWord& c = out.commands.emplace_back();
    c.name.assign(item.name);
    c.column = item.column;
    return c;
  };
  for (const Item& item : parsed_.items) {
    switch (item.kind) {
      case ItemKind::G: {
        const Support s = g_code_support(item.code);
        if (s == Support::Unknown) throw LineError(12470, item.column, "G" + std::to_string(item.code));
        if (s == Support::NotModelled) {
          warn_not_modelled("G" + std::to_string(item.code), item.column);
          break;
        }
        out.g.push_back(GWord{static_cast<int>(item.code), item.column});
        g_used_.set(static_cast<size_t>(item.code));
        has_words = true;
        break;
      }
      case ItemKind::M: {
        int64_t code = item.code;
        if (item.expr != kNoExpr) {
          const double v = eval(item.expr);
          if (v < 0 || v != std::trunc(v) || v > 999) throw LineError(12160, item.column, "M value must be an integer 0..999");
          code = static_cast<int64_t>(v);
        }
        if (code > 999) throw LineError(12160, item.column, "M value must be an integer 0..999");
        out.m.push_back(MWord{static_cast<int>(code), item.extension, item.column});
        m_used_.set(static_cast<size_t>(code));
        has_words = true;
        if (code == 17) action = PendingAction::Return;
        if (code == 2 || code == 30) action = PendingAction::EndProgram;
        break;
      }
      case ItemKind::Address:
        if (!is_address(item.name)) throw LineError(12550, item.column, "address " + std::string(item.name) + " not defined");
        out.addresses.push_back(AddressWord{std::string(item.name), parsed_.pool[item.expr].value, ValueMode::Default, item.column});
        has_words = true;
        break;
      case ItemKind::Assign: {
        if (item.name == "P" && item.index == kNoExpr) {
          // At most 9999 passes; checked before the conversion (out of range it is undefined).
          const double p = eval(item.expr);
          if (!(p <= 9999)) throw LineError(12160, item.column, "P (passes) must be at most 9999");
          passes = static_cast<uint64_t>(std::max(1.0, p));
          break;
        }
        if (item.index == kNoExpr && is_address(item.name) && !f.find_local(item.name)) {
          // X=R1*2, X=AC(5), X=IC(-1)
          const ExprNode& top = parsed_.pool[item.expr];
          ValueMode mode = ValueMode::Default;
          ExprIndex value_expr = item.expr;
          if (top.op == ExprOp::Call && (top.func == Function::AbsoluteMode || top.func == Function::IncrementalMode)) {
            mode = top.func == Function::AbsoluteMode ? ValueMode::Absolute : ValueMode::Incremental;
            value_expr = parsed_.pool.args[top.a];
          }
          out.addresses.push_back(AddressWord{std::string(item.name), eval(value_expr), mode, item.column});
          has_words = true;
          break;
        }
        assign(item);
        break;
      }
      case ItemKind::Procedure: {
        const Support s = command_support(item.name);
        if (s == Support::NotModelled) {
          warn_not_modelled(item.name, item.column);
          break;
        }
        if (s == Support::Modelled) {
          CommandWord& c = add_command(item);
          c.has_parentheses = true;
          for (uint32_t k = 0; k < item.arg_count; ++k) {
            const ExprIndex a = parsed_.pool.args[item.arg_first + k];
            if (a == kNoExpr) {
              c.args.emplace_back(std::string());
              continue;
            }
            const ExprNode& n = parsed_.pool[a];
            if (n.op == ExprOp::String) {
              c.args.emplace_back(std::string(n.text));
            } else if (n.op == ExprOp::Name && !f.find_local(n.text) && n.text != "TRUE" && n.text != "FALSE") {
              c.args.emplace_back(std::string(n.text));  // SPLINEPATH(1,X,Y,Z): axis names
            } else {
              c.args.emplace_back(eval(a));
            }
          }
          break;
        }
        if (is_expression_keyword(item.name))
          throw LineError(12080, item.column, "function " + std::string(item.name) + " used as a block word");
        // A subprogram with parameters: SUB(1, 2)
        if (!call_name.empty()) throw LineError(12080, item.column, "two program calls in one block");
        call_name.assign(item.name);
        call_column = item.column;
        for (uint32_t k = 0; k < item.arg_count; ++k) {
          const ExprIndex a = parsed_.pool.args[item.arg_first + k];
          pending_args_.push_back(a == kNoExpr ? 0.0 : eval(a));
        }
        break;
      }
      case ItemKind::Name: {
        const Support s = command_support(item.name);
        if (s == Support::NotModelled) {
          warn_not_modelled(item.name, item.column);
          break;
        }
        if (s == Support::Modelled) {
          add_command(item);
          if (item.name == "RET") action = PendingAction::Return;
          break;
        }
        if (f.find_local(item.name) || is_address(item.name))
          throw LineError(12080, item.column, std::string(item.name) + " without a value");
        if (is_expression_keyword(item.name))
          throw LineError(12080, item.column, "operator " + std::string(item.name) + " outside an expression");
        if (!call_name.empty()) {
          // Two bare words ("GOTOFF ENDE"): blame the one that looks like a misspelled command.
          std::string_view bad = item.name;
          uint32_t bad_column = item.column;
          std::string_view guess = near_miss(call_name);
          if (!guess.empty()) {
            bad = call_name;
            bad_column = call_column;
          } else {
            guess = near_miss(item.name);
          }
          throw LineError(12550, bad_column, "name " + std::string(bad) + " not defined" +
                                                 (guess.empty() ? "" : " (did you mean " + std::string(guess) + "?)"));
        }
        call_name.assign(item.name);
        call_column = item.column;
        break;
      }
      case ItemKind::ToolName:
        out.tool_name = std::string(item.name);
        has_words = true;
        break;
      case ItemKind::LCall:
        if (!call_name.empty()) throw LineError(12080, item.column, "two program calls in one block");
        call_name.assign(item.name);
        call_column = item.column;
        break;
      case ItemKind::Passes:
        passes = static_cast<uint64_t>(std::max<int64_t>(1, item.code));
        break;
    }
  }
  f.executed_block = f.executed_block || has_words || !call_name.empty();
  if (!call_name.empty()) {
    // A misspelled command next to other words is not a call: say what it probably is.
    if (has_words) {
      const std::string_view guess = near_miss(call_name);
      if (!guess.empty())
        throw LineError(12550, call_column, "name " + call_name + " not defined (did you mean " + std::string(guess) + "?)");
    }
    pending_ = PendingAction::Call;
    pending_call_ = call_name;
    pending_passes_ = passes;
    pending_column_ = call_column;
  }
  if (action != PendingAction::None) {
    if (pending_ == PendingAction::Call) throw LineError(12080, call_column, "program call and program end in one block");
    pending_ = action;
  }
  if (!has_words) return false;
  out.file = f.file;
  out.line = position_.line;
  out.text.assign(trimmed(text_));
  out.number = parsed_.number;
  out.program_level = static_cast<int>(frames_.size()) - 1;
  ++blocks_executed_;
  return true;
}

void ProgramLoader::execute_def() {
  Frame& f = *frames_.back();
  if (f.executed_block)
    throw LineError(14500, parsed_.statement_column, "DEF after the first executable block");
  for (const DefEntry& d : parsed_.defs) {
    Variable* existing = f.find_local(d.name);
    if (existing && existing->def_line != position_.line)
      throw LineError(12170, d.column, "name " + std::string(d.name) + " defined twice");
    if (!existing) {
      f.locals.push_back(Variable{std::string(d.name), std::string(parsed_.def_type), 0.0, {}, position_.line});
      existing = &f.locals.back();
    }
    existing->number = 0.0;
    existing->text.clear();
    if (d.init == kNoExpr) continue;
    const ExprNode& init = parsed_.pool[d.init];
    if (existing->type == "STRING" || existing->type == "CHAR" || existing->type == "AXIS") {
      if (init.op == ExprOp::String || init.op == ExprOp::Name) {
        existing->text.assign(init.text);
        continue;
      }
      if (existing->type == "STRING") throw LineError(12150, init.column, "STRING variable needs a string value");
    }
    if (init.op == ExprOp::String) throw LineError(12150, init.column, "string value for a numeric variable");
    const double v = eval(d.init);
    existing->number = existing->type == "INT" ? std::round(v) : existing->type == "BOOL" ? (v != 0.0 ? 1.0 : 0.0) : v;
  }
}

void ProgramLoader::execute_proc() {
  Frame& f = *frames_.back();
  for (size_t i = 0; i < parsed_.defs.size(); ++i) {
    const DefEntry& d = parsed_.defs[i];
    if (f.find_local(d.name)) continue;
    f.locals.push_back(Variable{std::string(d.name), "REAL", i < f.args.size() ? f.args[i] : 0.0, {}, position_.line});
  }
}

void ProgramLoader::push_control(const ControlFrame& c) {
  // Re-entering a structure (after a jump out of it) drops whatever was left above it.
  auto& stack = frames_.back()->control;
  for (size_t i = 0; i < stack.size(); ++i)
    if (stack[i].head.offset == c.head.offset) {
      stack.resize(i);
      break;
    }
  stack.push_back(c);
}

void ProgramLoader::execute_control() {
  Frame& f = *frames_.back();
  auto& stack = f.control;
  const Statement s = parsed_.statement;
  const uint32_t column = parsed_.statement_column;
  auto expect_top = [&](Statement opener) {
    if (stack.empty() || stack.back().kind != opener)
      throw LineError(12640, column, std::string(keyword(s)) + " without " + keyword(opener));
  };
  ControlFrame c;
  c.kind = s;
  c.head = position_;
  c.body = f.reader.tell();
  switch (s) {
    case Statement::If:
      if (eval(parsed_.condition) != 0.0) {
        push_control(c);
      } else if (skip_forward(true) == Statement::Else) {
        c.kind = Statement::If;
        push_control(c);
      }
      return;
    case Statement::Else:
      expect_top(Statement::If);
      stack.pop_back();
      skip_forward(false);
      return;
    case Statement::EndIf:
      expect_top(Statement::If);
      stack.pop_back();
      return;
    case Statement::While:
      if (eval(parsed_.condition) != 0.0)
        push_control(c);
      else
        skip_forward(false);
      return;
    case Statement::EndWhile: {
      expect_top(Statement::While);
      const LinePosition head = stack.back().head;
      stack.pop_back();
      f.reader.seek(head);  // the WHILE line evaluates its condition again
      return;
    }
    case Statement::For: {
      const std::string var(parsed_.for_variable);
      Item item;
      item.name = parsed_.for_variable;
      item.expr = parsed_.condition;
      item.column = column;
      assign(item);
      c.end = eval(parsed_.for_end);
      c.variable = var;
      const double start = eval(parsed_.condition);
      if (start > c.end)
        skip_forward(false);
      else
        push_control(c);
      return;
    }
    case Statement::EndFor: {
      expect_top(Statement::For);
      ControlFrame& top = stack.back();
      // Advance the loop variable: it is an R parameter or an INT/REAL variable.
      double value;
      if (Variable* v = f.find_local(top.variable)) {
        value = v->number = v->number + 1.0;
      } else {
        const double index = std::stod(top.variable.substr(1));
        value = r_parameters_[static_cast<size_t>(index)] += 1.0;
      }
      if (value <= top.end)
        f.reader.seek(top.body);
      else
        stack.pop_back();
      return;
    }
    case Statement::Repeat:
    case Statement::Loop:
      push_control(c);
      return;
    case Statement::Until:
      expect_top(Statement::Repeat);
      if (eval(parsed_.condition) == 0.0)
        f.reader.seek(stack.back().body);
      else
        stack.pop_back();
      return;
    case Statement::EndLoop:
      expect_top(Statement::Loop);
      f.reader.seek(stack.back().body);
      return;
    default:
      return;
  }
}

Statement ProgramLoader::skip_forward(bool stop_at_else) {
  // Skips the body of a structure whose condition is false: to the matching closer (or ELSE).
  Frame& f = *frames_.back();
  const LinePosition start = position_;
  const std::string start_text = text_;
  const Statement opener = parsed_.statement == Statement::Else ? Statement::If : parsed_.statement;
  int depth = 0;
  while (read_line(f)) {
    const std::string_view t = trimmed(text_);
    if (t.empty() || t.front() == ';' || t.front() == '%') continue;
    try {
      parser_.parse(text_, parsed_);
    } catch (const LineError& e) {
      raise(e.number(), e.detail(), e.column());
    }
    if (!parsed_.label.empty() && f.labels.size() < kMaxCachedLabels)
      f.labels.insert_or_assign(std::string(parsed_.label), position_);
    const Statement s = parsed_.statement;
    if (is_opener(s)) {
      ++depth;
    } else if (depth == 0 && stop_at_else && s == Statement::Else) {
      return s;
    } else if (is_closer(s)) {
      if (depth > 0) {
        --depth;
      } else {
        if (s != closer_of(opener))
          raise(12640, std::string(keyword(s)) + " where " + keyword(closer_of(opener)) + " was expected",
                parsed_.statement_column);
        return s;
      }
    }
  }
  position_ = start;
  text_ = start_text;
  raise(12640, std::string(keyword(opener)) + " without " + keyword(closer_of(opener)), 1);
}

void ProgramLoader::jump(JumpDirection direction, const std::string& label, std::optional<int64_t> number,
                         uint32_t column) {
  Frame& f = *frames_.back();
  const LinePosition from = position_;
  const LinePosition after = f.reader.tell();
  const std::string from_text = text_;
  auto matches = [&]() {
    return label.empty() ? parsed_.number == number : parsed_.label == label;
  };
  // Reads the next line for a search; false at end of file. Parses it (a line that cannot be
  // parsed stops the search with its own alarm).
  auto scan_line = [&]() {
    for (;;) {
      if (!f.reader.next(raw_)) return false;
      position_ = raw_.position;
      if (raw_.too_long) continue;
      decode_line_to_utf8(raw_.bytes, text_);
      const std::string_view t = trimmed(text_);
      if (t.empty() || t.front() == ';' || t.front() == '%') continue;
      try {
        parser_.parse(text_, parsed_);
      } catch (const LineError& e) {
        raise(e.number(), e.detail(), e.column());
      }
      if (!parsed_.label.empty() && f.labels.size() < kMaxCachedLabels)
        f.labels.insert_or_assign(std::string(parsed_.label), position_);
      return true;
    }
  };
  if (direction != JumpDirection::Backward) {
    // Forward: structures closed on the way are left, so their frames go.
    int depth = 0;
    while (scan_line()) {
      if (matches()) {
        f.reader.seek(position_);
        return;
      }
      if (is_opener(parsed_.statement)) ++depth;
      else if (is_closer(parsed_.statement)) {
        if (depth > 0) --depth;
        else if (!f.control.empty()) f.control.pop_back();
      }
    }
  }
  if (direction != JumpDirection::Forward) {
    std::optional<LinePosition> found;
    if (!label.empty()) {
      if (auto it = f.labels.find(label); it != f.labels.end() && it->second.line < from.line) found = it->second;
    }
    if (!found) {
      f.reader.seek(LinePosition{});
      while (scan_line() && position_.line < from.line)
        if (matches()) found = position_;
    }
    if (found) {
      // Structures that start at or after the target are left (and entered again later).
      auto& stack = f.control;
      while (!stack.empty() && stack.back().head.line >= found->line) stack.pop_back();
      f.reader.seek(*found);
      return;
    }
  }
  position_ = from;
  text_ = from_text;
  if (direction == JumpDirection::NoAlarm) {
    f.reader.seek(after);
    return;
  }
  raise(14080, label.empty() ? "N" + std::to_string(*number) : label, column);
}

void ProgramLoader::call_program(const std::string& written_name, uint64_t passes, uint32_t column) {
  if (static_cast<int>(frames_.size()) > kMaxProgramLevel)
    raise(990003, "calling " + written_name, column);
  const ProgramName name = normalize_program_name(written_name);
  const auto path = files_->find(name);
  if (!path) {
    const std::string_view guess = near_miss(name.name);
    if (!guess.empty())
      raise(12550, "name " + name.name + " not defined (did you mean " + std::string(guess) + "?)", column);
    raise(14011, "program " + name.name + " not found in the search path", column);
  }
  auto frame = std::make_unique<Frame>();
  if (!frame->reader.open(*path)) raise(990005, path->string(), column);
  frame->file = std::make_shared<const std::string>(path->string());
  frame->program = name.name;
  frame->passes_left = std::max<uint64_t>(1, passes);
  frame->args = pending_args_;
  pending_args_.clear();
  if (std::find(programs_used_.begin(), programs_used_.end(), name.name) == programs_used_.end())
    programs_used_.push_back(name.name);
  frames_.push_back(std::move(frame));
}

void ProgramLoader::end_of_file() {
  Frame& f = *frames_.back();
  if (!f.control.empty()) {
    const ControlFrame& open = f.control.back();
    position_ = open.head;
    text_.clear();
    raise(12640, std::string(keyword(open.kind)) + " without " + keyword(closer_of(open.kind)), 1);
  }
  if (frames_.size() == 1 && !main_has_content_) {
    position_ = LinePosition{0, 1};
    text_.clear();
    raise(990010, "", 1);
  }
  finish_frame();
}

void ProgramLoader::finish_frame() {
  Frame& f = *frames_.back();
  if (f.passes_left > 1) {  // next pass of a subprogram called with P
    --f.passes_left;
    f.control.clear();
    f.locals.clear();
    f.executed_block = false;
    f.reader.seek(LinePosition{});
    return;
  }
  frames_.pop_back();
}

}  // namespace drycut::parser
