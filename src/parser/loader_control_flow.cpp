// Control flow of the loader: structured loops and IF (PGA Job Planning "Program flow control"),
// jumps GOTOF/GOTOB/GOTO/GOTOC to labels, block numbers or computed targets, CASE, and program
// section repetition REPEAT/REPEATB.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "parser/ascii_case.hpp"
#include "parser/line_error.hpp"
#include "parser/loader_frame.hpp"
#include "parser/text_decoding.hpp"

namespace drycut::parser {

namespace {
constexpr size_t kMaxCachedLabels = 100000;
}

namespace {

// The block number and label of a line the parser refuses, from its text ("N10 LBL: ...",
// "LBL: N10 ..."), so that a jump over it or to it still finds them.
void head_of_unparsable_line(std::string_view t, std::optional<int64_t>& number, std::string& label) {
  size_t i = 0;
  auto blanks = [&] {
    while (i < t.size() && is_blank_char(t[i])) ++i;
  };
  auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  blanks();
  if (i < t.size() && t[i] == '/') i += (i + 1 < t.size() && std::isdigit(static_cast<unsigned char>(t[i + 1]))) ? 2 : 1;
  for (int round = 0; round < 2; ++round) {
    blanks();
    size_t j = i;
    if (j < t.size() && (t[j] == 'N' || t[j] == 'n') && j + 1 < t.size() && std::isdigit(static_cast<unsigned char>(t[j + 1]))) {
      int64_t n = 0;
      for (++j; j < t.size() && std::isdigit(static_cast<unsigned char>(t[j])) && n < 100000000000LL; ++j) n = n * 10 + (t[j] - '0');
      number = n;
      i = j;
      continue;
    }
    if (j < t.size() && letter(t[j])) {
      while (j < t.size() && (letter(t[j]) || std::isdigit(static_cast<unsigned char>(t[j])))) ++j;
      size_t k = j;
      while (k < t.size() && is_blank_char(t[k])) ++k;
      if (k < t.size() && t[k] == ':') {
        label = upper_ascii(t.substr(i, j - i));
        i = k + 1;
      }
    }
  }
}

}  // namespace

void ProgramLoader::parse_during_search(Frame& f) {
  // A line read while skipping or searching: parsed for its structure and its label, which is
  // remembered, so a later backward jump finds it without reading the file again. A line the
  // control does not execute raises no syntax alarm (it is only read when it runs): it counts
  // as an ordinary block with the number and label its text shows.
  try {
    parser_.parse(text_, parsed_);
  } catch (const LineError&) {
    parsed_.clear();
    search_label_.clear();
    head_of_unparsable_line(text_, parsed_.number, search_label_);
    parsed_.label = search_label_;
  }
  if (!parsed_.label.empty() && f.labels.size() < kMaxCachedLabels)
    f.labels.insert_or_assign(std::string(parsed_.label), position_);
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
      throw LineError(12640, column, std::string(statement_keyword(s)) + " without " + statement_keyword(opener));
  };
  ControlFrame c;
  c.kind = s;
  c.head = position_;
  c.body = f.reader.tell();
  switch (s) {
    case Statement::If:
      if (eval(parsed_.condition) != 0.0) {
        c.awaited_input = condition_input();
        push_control(c);
      } else if (c.awaited_input = condition_input(); skip_forward(true) == Statement::Else) {
        c.kind = Statement::If;
        c.in_else = true;
        push_control(c);
      }
      return;
    case Statement::Else:
      expect_top(Statement::If);
      // One ELSE per IF (Job Planning, "Program branches IF-ELSE-ENDIF"): a second one is the
      // control's nesting alarm, not a second alternative (before 2026-11-28 it ran silently).
      if (stack.back().in_else) throw LineError(12640, column, "second ELSE in one IF");
      stack.pop_back();
      skip_forward(false);
      return;
    case Statement::EndIf:
      expect_top(Statement::If);
      stack.pop_back();
      return;
    case Statement::While:
      if (eval(parsed_.condition) != 0.0) {
        c.awaited_input = condition_input();
        push_control(c);
      } else
        skip_forward(false);
      return;
    case Statement::EndWhile: {
      expect_top(Statement::While);
      const LinePosition head = stack.back().head;
      const std::string awaited = stack.back().awaited_input;
      const LinePosition after = f.reader.tell();
      stack.pop_back();
      f.reader.seek(head);  // the WHILE line evaluates its condition again
      if (check_endless_loop(awaited)) f.reader.seek(after);  // the awaited input came: the loop ends
      return;
    }
    case Statement::For:
      start_for_loop(c, column);
      return;
    case Statement::EndFor:
      expect_top(Statement::For);
      next_for_pass(f, column);
      return;
    case Statement::Repeat:
    case Statement::Loop:
      push_control(c);
      return;
    case Statement::Until:
      expect_top(Statement::Repeat);
      if (eval(parsed_.condition) == 0.0)
        repeat_loop_body(f, condition_input());
      else
        stack.pop_back();
      return;
    case Statement::EndLoop:
      expect_top(Statement::Loop);
      repeat_loop_body(f);  // it waits for an input (and jumps out when it comes)
      return;
    default:
      return;
  }
}

// FOR: sets the loop variable (an INT/REAL variable or an R parameter) to the start value and
// enters the body, or skips it when the start is beyond the end.
void ProgramLoader::start_for_loop(ControlFrame& c, uint32_t column) {
  const double start = eval(parsed_.condition);
  c.end = eval(parsed_.for_end);
  c.variable = std::string(parsed_.for_variable);
  if (Variable* v = find_variable(c.variable)) {
    v->set(v->element({}, column), Value(start), column);
  } else if (c.variable.size() >= 2 && c.variable[0] == 'R' &&
             c.variable.find_first_not_of("0123456789", 1) == std::string::npos) {  // R<n>, not RX
    assign_r_parameter(std::stod(c.variable.substr(1)), start, column);
  } else {
    throw LineError(12550, column, "FOR variable " + c.variable + " not defined");
  }
  if (start > c.end)
    skip_forward(false);
  else
    push_control(c);
}

// ENDFOR: advances the loop variable of the innermost FOR (an INT/REAL variable or an R
// parameter) and runs the body again while it has not passed the end value.
void ProgramLoader::next_for_pass(Frame& f, uint32_t column) {
  ControlFrame& top = f.control.back();
  double value;
  if (Variable* v = find_variable(top.variable)) {
    const size_t e = v->element({}, column);
    value = v->get(e).number + 1.0;
    v->set(e, Value(value), column);
  } else {
    const double index = std::stod(top.variable.substr(1));
    value = r_parameters_[static_cast<size_t>(index)] += 1.0;
  }
  if (value <= top.end) {
    f.reader.seek(top.body);  // the variable changed: never the same state, but a FOR whose
    // pass read an input may count the timeout of a wait for it (checked only then: FOR loops
    // that compute run 400 k passes in a CAM macro)
    if (system_variables_.input_reads() != input_reads_at_endfor_) check_endless_loop();
    input_reads_at_endfor_ = system_variables_.input_reads();
  } else
    f.control.pop_back();
}

// UNTIL (condition false) and ENDLOOP: back to the body of the innermost REPEAT / LOOP, unless
// the endless-loop check finds the loop waiting for an input that came: then the loop ends.
void ProgramLoader::repeat_loop_body(Frame& f, const std::string& awaited) {
  const LinePosition after = f.reader.tell();
  f.reader.seek(f.control.back().body);
  if (check_endless_loop(awaited)) {  // the awaited input came: the loop ends
    f.reader.seek(after);
    f.control.pop_back();
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
    if (is_blank_or_comment(text_)) continue;
    parse_during_search(f);
    const Statement s = parsed_.statement;
    if (is_opener(s)) {
      ++depth;
    } else if (depth == 0 && s == Statement::Else && opener == Statement::If) {
      if (stop_at_else) return s;
      // Skipping the ELSE part to its ENDIF: a second ELSE of the same IF.
      raise(12640, "second ELSE in one IF", parsed_.statement_column);
    } else if (is_closer(s)) {
      if (depth > 0) {
        --depth;
      } else {
        if (s != closer_of(opener))
          raise(12640, std::string(statement_keyword(s)) + " where " + statement_keyword(closer_of(opener)) + " was expected",
                parsed_.statement_column);
        return s;
      }
    }
  }
  position_ = start;
  text_ = start_text;
  raise(12640, std::string(statement_keyword(opener)) + " without " + statement_keyword(closer_of(opener)), 1);
}

void ProgramLoader::jump(JumpDirection direction, const JumpTarget& target) {
  if (direction == JumpDirection::ToStart) {
    jump_to_start();
    return;
  }
  if (target.expr != kNoExpr) {
    jump_to_value(direction, eval_value(target.expr), target.column);
    return;
  }
  if (!target.label.empty()) {
    // GOTOF NAME: a STRING variable holding the label, or the label itself.
    if (Variable* v = find_variable(target.label); v && v->type() == DataType::String && v->rank() == 0) {
      jump_to_value(direction, v->get(0), target.column);
      return;
    }
  }
  jump_to(direction, std::string(target.label), target.number, target.column);
}

namespace {
// "N50" as a jump target or section marker (GOTOF "N"<<R1, REPEAT N50 P=2): block number 50. A label cannot be N and digits
// (its first two characters are letters or underscores), so the two never mix.
std::optional<int64_t> marker_block_number(const std::string& marker) {
  if (marker.size() < 2 || marker.size() > 19 || marker[0] != 'N') return std::nullopt;
  if (!std::all_of(marker.begin() + 1, marker.end(), [](char c) { return c >= '0' && c <= '9'; })) return std::nullopt;
  return std::stoll(marker.substr(1));
}
}  // namespace

void ProgramLoader::jump_to_value(JumpDirection direction, const Value& target, uint32_t column) {
  // A computed target: a number is a block number; a string a label, or a block number when it
  // reads "N<digits>" (Job Planning: the STRING stands for a jump marker or a block number; a
  // label cannot look like that, its first two characters are letters or underscores).
  if (target.is_number()) {
    jump_to(direction, {}, block_number_of(target.number), column);
    return;
  }
  const std::string text = upper_ascii(target.text);
  if (const auto number = marker_block_number(text)) jump_to(direction, {}, number, column);
  else jump_to(direction, text, std::nullopt, column);
}

void ProgramLoader::jump_to_start() {
  // GOTOS (Job Planning, "Program jumps: GOTOS"): back to the beginning of the program, that is
  // its first block after the PROC line, definitions and declarations (those ran once).
  Frame& f = *frames_.back();
  f.reader.seek(f.start);
  LinePosition first = f.start;
  while (f.reader.next(raw_)) {
    position_ = raw_.position;
    if (raw_.too_long) continue;
    decode_line_to_utf8(raw_.bytes, text_);
    if (is_blank_or_comment(text_)) continue;
    parse_during_search(f);
    const Statement s = parsed_.statement;
    if (s == Statement::Def || s == Statement::Proc || s == Statement::Extern || s == Statement::Define) continue;
    first = position_;
    break;
  }
  f.control.clear();
  f.reader.seek(first);
  if (check_endless_loop())
    raise(990004, "GOTOS back to the start while waiting for " + system_variables_.last_input_read(), 0);
}

void ProgramLoader::jump_to(JumpDirection direction, const std::string& label, std::optional<int64_t> number,
                            uint32_t column) {
  Frame& f = *frames_.back();
  const LinePosition from = position_;
  const LinePosition after = f.reader.tell();
  const std::string from_text = text_;
  auto matches = [&]() { return label.empty() ? parsed_.number == number : parsed_.label == label; };
  // Reads the next line for a search; false at end of file. Parses it (a line that cannot be
  // parsed counts with the number and label of its text: parse_during_search).
  auto scan_line = [&]() {
    for (;;) {
      if (!f.reader.next(raw_)) return false;
      if (raw_.position.offset > f.start.offset && is_program_header(raw_.bytes)) return false;  // the next program
      position_ = raw_.position;
      if (raw_.too_long) continue;
      decode_line_to_utf8(raw_.bytes, text_);
      if (is_blank_or_comment(text_)) continue;
      parse_during_search(f);
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
      if (auto it = f.labels.find(label); it != f.labels.end() && it->second.line <= from.line) found = it->second;
    }
    if (!found) {
      // The jumping block itself is a target too: WAIT: IF $A_IN[1]==0 GOTOB WAIT.
      f.reader.seek(f.start);
      while (scan_line() && position_.line <= from.line)
        if (matches()) found = position_;
      position_ = from;  // the search read on past the jump: an alarm of the jump names its block
      text_ = from_text;
    }
    if (found) {
      const std::string awaited = jump_awaited_input(found->line);
      // Structures that start at or after the target are left (and entered again later).
      auto& stack = f.control;
      size_t kept = stack.size();
      while (kept > 0 && stack[kept - 1].head.line >= found->line) --kept;
      std::vector<ControlFrame> left(stack.begin() + static_cast<std::ptrdiff_t>(kept), stack.end());
      stack.resize(kept);
      f.reader.seek(*found);
      if (check_endless_loop(awaited)) {  // the awaited input came: the jump back is not taken
        stack.insert(stack.end(), left.begin(), left.end());
        f.reader.seek(after);
      }
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

void ProgramLoader::execute_if_goto() {
  // IF c1 GOTOF l1 [IF c2 GOTOF l2 ...]: the first condition that holds jumps; none: the next block.
  if (eval(parsed_.condition) != 0.0) {
    note_input_jump();
    jump(parsed_.jump, parsed_.target);
    return;
  }
  std::string input = condition_input();
  const std::vector<CaseBranch> more = parsed_.cases;  // the jump reuses parsed_
  for (const CaseBranch& b : more)
    if (eval(b.value) != 0.0) {
      note_input_jump();
      jump(b.jump, b.target);
      return;
    }
  // A PLC byte or word that decided not to jump (TC_WAIT: IF $A_DBB[100]==1 GOTOF TC_OK, in a
  // poll whose counter times out) decides the alarm that follows as much: a dry run cannot make
  // it come (it has no one awaited value, as a digital input has), so the timeout's SETAL within
  // the lines after it is the signal's, not the machine's state (990021).
  if (input.starts_with("$A_DB") && !system_variables_.signal_given(input)) input_jump_ = {std::move(input), steps_};
}

void ProgramLoader::note_input_jump() {
  if (std::string input = condition_input(); !input.empty()) input_jump_ = {std::move(input), steps_};
}

std::string ProgramLoader::alarm_decided_by_unknown_input(int alarm) const {
  // The IF (or ELSE) blocks the alarm stands in, innermost first, those of the calling levels
  // too (IF $A_IN[5]==0 / OEM_ALARM(65000, ...): the builder's central alarm program), then a
  // jump decided by an input that arrived here within the lines of an error branch (IF
  // $A_IN[12]==0 GOTOF ERR / ERR: MSG, M5 M9, a retract, SETAL), then a measured value read
  // before.
  constexpr uint64_t kLinesAfterJump = 10;
  for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame)
    for (auto it = (*frame)->control.rbegin(); it != (*frame)->control.rend(); ++it)
      if (it->kind == Statement::If && !it->awaited_input.empty() && !system_variables_.signal_given(it->awaited_input))
        return it->awaited_input;
  if (!input_jump_.first.empty() && steps_ - input_jump_.second <= kLinesAfterJump &&
      !system_variables_.signal_given(input_jump_.first))
    return input_jump_.first;
  // After a measurement every check of the program's own alarms (60000..60999, 65000..69999;
  // not the standard cycles' 61000..64999, which check their parameters) may hang on the
  // measured value through the variables the macro computes from it (_D=_XP-_XM, IF _D>20.5
  // SETAL): a dry run measured nothing.
  const bool own_alarm = alarm < 61000 || alarm >= 65000;
  return own_alarm ? system_variables_.measurement_read() : std::string();
}

void ProgramLoader::execute_case() {
  // CASE expr OF c1 GOTOF l1 c2 GOTOF l2 DEFAULT GOTOF l3: the first constant equal to the
  // value jumps; none -> DEFAULT; no DEFAULT -> the next block.
  const Value v = eval_value(parsed_.condition);
  const std::vector<CaseBranch> branches = parsed_.cases;  // the jump reuses parsed_
  for (const CaseBranch& b : branches) {
    bool hit = b.value == kNoExpr;
    if (!hit) {
      // A CHAR holds its code: it equals a one-character constant "B" (and the other way round).
      const auto code = [](const Value& x) -> std::optional<double> {
        if (x.is_number()) return x.number;
        if (x.is_text() && x.text.size() == 1) return static_cast<unsigned char>(x.text[0]);
        return std::nullopt;
      };
      const Value c = eval_value(b.value);
      if (c.is_number() != v.is_number()) {
        const auto a = code(c), d = code(v);
        hit = a && d && real_equal(*a, *d);
      } else {
        hit = c.is_number() ? real_equal(c.number, v.number) : c.text == v.text;
      }
    }
    if (hit) {
      JumpTarget target = b.target;
      std::string label(target.label);  // the view points into the parsed line
      if (target.expr != kNoExpr) {
        jump(b.jump, target);
      } else {
        jump_to(b.jump, label, target.number, target.column);
      }
      return;
    }
  }
}

std::optional<LinePosition> ProgramLoader::find_label_position(const std::string& label) {
  Frame& f = *frames_.back();
  if (marker_block_number(label)) {
    // A block number may come more than once: the last one up to this line, else the next one.
    if (auto before = find_label_between(label, f.start, f.reader.tell().offset, true)) return before;
    return find_label_between(label, f.reader.tell(), UINT64_MAX);
  }
  if (auto it = f.labels.find(label); it != f.labels.end()) return it->second;
  // Not passed yet: search the whole program.
  return find_label_between(label, f.start, UINT64_MAX);
}

std::optional<LinePosition> ProgramLoader::find_label_between(const std::string& label, LinePosition from,
                                                               uint64_t before, bool last) {
  // A parser of its own (the current line's parse stays valid); reading goes on where it was.
  Frame& f = *frames_.back();
  const LinePosition resume = f.reader.tell();
  const std::optional<int64_t> number = marker_block_number(label);
  std::optional<LinePosition> found;
  f.reader.seek(from);
  RawLine raw;
  std::string line;
  ParsedLine parsed;
  LineParser parser;
  while ((last || !found) && f.reader.next(raw) && raw.position.offset < before) {
    if (raw.position.offset > from.offset && is_program_header(raw.bytes)) break;  // the next program
    if (raw.too_long) continue;
    decode_line_to_utf8(raw.bytes, line);
    if (is_blank_or_comment(line)) continue;
    try {
      parser.parse(line, parsed);
    } catch (const LineError&) {
      continue;  // a broken line raises its alarm when it is executed, not here
    }
    if (number ? parsed.number == number : parsed.label == label) found = raw.position;
  }
  f.reader.seek(resume);
  return found;
}

void ProgramLoader::execute_repeat_section() {
  // REPEAT start P=n: lines from label `start` up to the first line labelled ENDLABEL after it,
  // inclusive, or without one up to this REPEAT line; REPEAT start end P=n: from `start` to the
  // line labelled `end`, inclusive; REPEATB label P=n: that one line.
  // The section runs n more times (P=1 when not written), then reading goes on after REPEAT.
  Frame& f = *frames_.back();
  double passes = 1;
  if (parsed_.passes != kNoExpr) passes = eval(parsed_.passes);
  if (!(passes >= 0 && passes <= 9999)) throw LineError(12160, parsed_.target.column, "P must be 0..9999");
  const std::string start_label = parsed_.call_block ? section_label(parsed_.call_name) : std::string(parsed_.call_name);
  const std::string end_label = parsed_.call_block ? section_label(parsed_.end_label) : std::string(parsed_.end_label);
  const bool one_block = parsed_.repeat_one_block;
  const uint32_t column = parsed_.target.column;
  const LinePosition repeat_line = position_;
  RepeatSection r;
  r.resume = f.reader.tell();
  r.remaining = static_cast<uint64_t>(passes);
  const auto start = find_label_position(start_label);
  if (!start) throw LineError(14080, column, start_label);
  r.start = *start;
  // ENDLABEL ends a section programmed before the REPEAT line between its start and the REPEAT
  // line; one after it (a forward start label) anywhere after its start.
  std::optional<LinePosition> end_line;
  if (!one_block && end_label.empty())
    end_line = find_label_between("ENDLABEL", r.start, r.start.offset < repeat_line.offset ? repeat_line.offset : UINT64_MAX);
  if (one_block || !end_label.empty() || end_line) {
    const auto end = one_block ? start : end_line ? end_line : find_label_between(end_label, r.start, UINT64_MAX);
    if (!end) throw LineError(14080, column, end_label);
    // The section ends after the end line: find where the next line starts.
    f.reader.seek(*end);
    RawLine raw;
    f.reader.next(raw);
    r.stop_offset = f.reader.tell().offset;
  } else {
    r.stop_offset = repeat_line.offset;
  }
  if (r.remaining == 0 || r.stop_offset <= r.start.offset) {
    f.reader.seek(r.resume);
    return;
  }
  // Each open section occupies a program level (Job Planning, "Program section repetition"):
  // a section that contains its own REPEAT (REPEATB on its own label) nests without end.
  size_t levels = frames_.size();
  for (const auto& frame : frames_) levels += frame->repeats.size();
  if (levels > static_cast<size_t>(kMaxProgramLevel))
    throw LineError(990003, column, "REPEAT " + start_label);
  --r.remaining;
  f.repeats.push_back(r);
  f.reader.seek(r.start);
}

void ProgramLoader::loop_state(std::string& out) const {
  out.clear();
  auto put = [&out](const auto& v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
  for (const auto& frame : frames_) {
    put(frame->file);
    put(frame->reader.tell().offset);
    put(frame->passes_left);
    for (const auto& c : frame->control) {
      put(c.head.offset);
      put(c.end);
    }
    for (const auto& r : frame->repeats) put(r.remaining);
    frame->locals.append_state(out);
  }
  put(r_used_);
  out.append(reinterpret_cast<const char*>(r_parameters_.data()), r_used_ * sizeof(double));
  globals_.append_state(out);
  system_variables_.append_state(out);
  put(macros_.size());
}

std::string ProgramLoader::condition_input() const {
  return system_variables_.input_reads() != input_reads_at_line_ ? system_variables_.last_input_read() : std::string();
}

std::string ProgramLoader::jump_awaited_input(uint32_t target_line) const {
  if (std::string on_line = condition_input(); !on_line.empty() || parsed_.statement != Statement::Goto) return on_line;
  const auto& stack = frames_.back()->control;
  if (!stack.empty() && stack.back().kind == Statement::If && stack.back().head.line >= target_line)
    return stack.back().awaited_input;
  return {};
}

bool ProgramLoader::check_endless_loop(const std::string& awaited) {
  // A big state (large arrays) is compared only every state-size/1 KiB lines, so that the guard
  // costs at most about 1 KiB of copying per line executed; states up to 1 KiB are compared at
  // every jump. Skipping visits never gives a false alarm, and a loop is still found: the visits
  // that are checked form a deterministic sequence too, so they repeat as well. A loop that
  // reads an input is checked at every jump back: where a wait on a signal ends (and so how many
  // passes of its dwell count) must not depend on how big the global data are (the measuring
  // cycles' GUD arrays made such waits run passes more).
  constexpr uint64_t kStateBytesPerLine = 1024;
  const bool polls_input = !awaited.empty() || system_variables_.input_reads() != input_reads_at_loop_check_;
  if (steps_ < next_loop_check_ && !polls_input) return false;
  input_reads_at_loop_check_ = system_variables_.input_reads();
  const Frame& f = *frames_.back();
  // The site: where the jump goes, in which program at which depth.
  const uint64_t site = (f.reader.tell().offset * 31 + reinterpret_cast<uintptr_t>(f.file)) * 17 + frames_.size();
  loop_state(loop_state_);
  next_loop_check_ = steps_ + loop_state_.size() / kStateBytesPerLine;
  const LoopGuard::Visit visit{system_variables_.view_reads(), system_variables_.input_reads(), work_blocks_,
                               dwell_blocks_, system_variables_.clock_reads(), system_variables_.process_reads(),
                               !awaited.empty(), system_variables_.elapsed_s()};
  switch (loop_guard_.repeats(site, loop_state_, visit)) {
    case LoopGuard::Repeat::No:
      system_variables_.forget_settled_read();  // only a read of the pass that repeats is named
      return false;
    case LoopGuard::Repeat::PollsInputWithTimeout: {
      // A wait with a counter for its timeout: the input comes (a digital input toggles), and
      // the loop leaves by its own jump on the next pass. Other signals keep their value.
      const std::string what = system_variables_.last_input_read();
      if (system_variables_.input_arrived(what))
        warn(990014, "loop waits for " + what + " (its pass counts a timeout; the input is taken as come)", 0);
      return false;
    }
    case LoopGuard::Repeat::Endless: {
      // A poll of an actual value (spindle speed, axis position) that no longer changes: the
      // value the loop waits for is beyond what the machine reaches, which the alarm says.
      const std::string& settled = system_variables_.settled_read();
      raise(990004,
            "back at line " + std::to_string(f.reader.tell().line) + " with every variable unchanged" +
                (settled.empty() ? std::string() : " (" + settled + ")"),
            0);
    }
    case LoopGuard::Repeat::WaitsOnInput:
      // On the machine the PLC or the process changes the input and the wait ends; a dry run
      // has neither, so the wait ends at once and takes no time (docs/controller-state.md).
    {
      // Only an input or PLC datum can be given a value in the profile; the operator at M0 and
      // a synchronized action's variables cannot.
      const std::string what = awaited.empty() ? system_variables_.last_input_read() : awaited;
      const bool signal = classify_system_variable(what.substr(0, what.find('['))) == SystemVariableClass::InputOutput;
      warn(990014, "loop waits for " + what + (signal ? " (give it a value in the profile's machine_data to model the signal)" : ""),
           0);
      // The signal came: a check after the wait (IF $A_IN[9]==0 SETAL(...)) sees it. Only the
      // input the loop's condition waits for (not one the body read besides).
      if (!awaited.empty()) system_variables_.input_arrived(awaited);
    }
      return true;
  }
  return false;
}

// A label of CALL [..] BLOCK as written: the value of a STRING variable of that name, else the
// label itself (a string constant's text, in upper case as labels are read).
std::string ProgramLoader::section_label(std::string_view written) {
  if (const Variable* v = find_variable(written); v && v->type() == DataType::String && v->rank() == 0)
    return upper_ascii(v->get(0).text);
  return upper_ascii(written);
}

void ProgramLoader::run_program_section(const std::string& start_label, const std::string& end_label, uint32_t column) {
  // CALL "PROG" BLOCK start TO end (Job Planning, "Indirect call of a program part"): the called
  // program runs from label `start` to the line labelled `end`, inclusive, and returns: a
  // section run once whose reading goes on at the end of the file.
  Frame& f = *frames_.back();
  const auto start = find_label_position(start_label);
  if (!start) throw LineError(14080, column, start_label + " in " + f.program);
  // The end is the first line labelled `end` from the start on: CAM posts close every embedded
  // section with the same label (Fusion: LABELn: ... LABEL0:), so an earlier one does not count.
  const auto end = find_label_between(end_label, *start, UINT64_MAX);
  if (!end) throw LineError(14080, column, end_label + " after " + start_label + " in " + f.program);
  RawLine raw;
  f.reader.seek(*end);
  f.reader.next(raw);
  RepeatSection r;
  r.start = *start;
  r.stop_offset = f.reader.tell().offset;
  while (f.reader.next(raw)) {
  }
  r.resume = f.reader.tell();
  if (r.stop_offset > r.start.offset) {
    f.repeats.push_back(r);
    f.reader.seek(r.start);
  }
}

bool ProgramLoader::end_of_repeat_section(Frame& f) {
  RepeatSection& r = f.repeats.back();
  if (position_.offset != r.stop_offset) return false;
  if (r.remaining > 0) {
    --r.remaining;  // the count changed: never the same state
    f.reader.seek(r.start);
  } else {
    f.reader.seek(r.resume);
    f.repeats.pop_back();
  }
  return true;
}

}  // namespace drycut::parser
