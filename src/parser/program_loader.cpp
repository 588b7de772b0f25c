#include "parser/program_loader.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "parser/command_table.hpp"
#include "parser/expression_evaluator.hpp"
#include "parser/line_error.hpp"
#include "parser/loader_frame.hpp"
#include "parser/text_decoding.hpp"

namespace drycut::parser {

namespace {

constexpr size_t kMaxCachedLabels = 100000;
constexpr size_t kMaxWarnings = 10000;
constexpr size_t kRParameterCount = 1000;  // R0 .. R999

}  // namespace

ProgramLoader::ProgramLoader(LoaderOptions options, Diagnostics& diagnostics)
    : options_(std::move(options)),
      diagnostics_(diagnostics),
      scope_(std::make_unique<Scope>(*this)),
      r_parameters_(kRParameterCount, 0.0),
      system_variables_(options_.machine_data, options_.machine_data_texts) {
  const auto scope = options_.machine_data.find("$MN_LUD_EXTENDED_SCOPE");
  program_global_data_ = scope != options_.machine_data.end() && scope->second != 0.0;
}

ProgramLoader::~ProgramLoader() = default;

// A file may begin with blank, comment or tape-leader lines before its own header
// (%_N_NAME_MPF): then that header starts the program rather than ending it as the next program
// of an archive would (punched-tape format: the header belongs in the first line, but editors
// and DNC software put lines before it). Leaves the reader at the program's start.
void ProgramLoader::start_at_own_header(Frame& f) {
  const LinePosition begin = f.reader.tell();
  RawLine raw;
  std::string text;
  while (f.reader.next(raw)) {
    std::string_view bytes = raw.bytes;
    if (raw.position.offset == 0 && bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);  // a UTF-8 BOM
    if (is_program_header(bytes)) {
      f.start = raw.position;
      f.reader.seek(raw.position);
      return;
    }
    if (raw.too_long) break;
    decode_line_to_utf8(bytes, text);
    if (!is_blank_or_comment(text)) break;
  }
  f.reader.seek(begin);
}

void ProgramLoader::open_main(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw UsageError("cannot read program '" + path.string() + "': no such file");
  auto frame = std::make_unique<Frame>();
  if (!frame->reader.open(path)) throw UsageError("cannot open program '" + path.string() + "'");
  start_at_own_header(*frame);
  frame->file = intern_file_name(path.string());
  frame->program = normalize_program_name(path.stem().string() + path.extension().string()).name;
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::vector<std::filesystem::path> dirs{folder};
  for (const auto& d : options_.search_path) dirs.push_back(d);
  files_ = std::make_unique<ProgramFiles>(std::move(dirs));
  programs_used_.push_back(frame->program);
  frames_.clear();
  try {
    read_definition_files(folder);
  } catch (const AlarmError& e) {
    // Raised where callers handle the program's alarms (the block loop), not as a usage error.
    definition_alarm_ = e.alarm();
    frames_.clear();
  }
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

Value ProgramLoader::eval_value(ExprIndex e) const {
  Value v = evaluate_value(parsed_.pool, e, *scope_);
  if (v.is_number() && !std::isfinite(v.number)) raise(14051, "result is not a finite number", parsed_.pool[e].column);
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

void ProgramLoader::count_line() {
  system_variables_.begin_line();
  input_reads_at_line_ = system_variables_.input_reads();
  if (++steps_ > options_.max_steps) {
    text_.clear();
    raise(990004, "more than " + std::to_string(options_.max_steps) + " lines executed", 0);
  }
}

bool ProgramLoader::take_pending_line() {
  // EXECSTRING: its text runs as a line of its own, at the position of the EXECSTRING line, before
  // what that block asked for next (a call, the return, the end). A string that runs
  // EXECSTRING again and again is an endless loop.
  constexpr int kMaxExecStringChain = 1000;
  text_ = std::move(*pending_line_);
  pending_line_.reset();
  if (++exec_string_chain_ > kMaxExecStringChain)
    raise(990004, "EXECSTRING runs EXECSTRING more than " + std::to_string(kMaxExecStringChain) + " times in a row", 0);
  count_line();
  if (!macros_.empty() && may_hold_macro()) expand_macros();
  return !is_blank_or_comment(text_);
}

bool ProgramLoader::read_line(Frame& f) {
  for (;;) {
    bool got = f.reader.next(raw_);
    if (got && raw_.position.offset > f.start.offset && is_program_header(raw_.bytes)) {
      // The next program of an archive file begins: this one ends before its header.
      f.reader.set_end(raw_.position.offset);
      f.reader.seek(raw_.position);
      got = false;
    }
    if (!got) {
      if (f.reader.read_error()) raise(990005, "read error in " + *f.file, 0);
      position_ = f.reader.tell();  // a REPEAT section may end with the file
      if (!f.repeats.empty() && end_of_repeat_section(f)) continue;
      return false;
    }
    position_ = raw_.position;
    if (!f.repeats.empty() && end_of_repeat_section(f)) continue;
    break;
  }
  count_line();
  exec_string_chain_ = 0;
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
  if (!macros_.empty() && may_hold_macro()) expand_macros();
  return true;
}

bool ProgramLoader::next(Block& out) {
  if (definition_alarm_) {
    const Alarm alarm = std::move(*definition_alarm_);
    definition_alarm_.reset();
    throw AlarmError(alarm);
  }
  for (;;) {
    if (pending_line_ && !frames_.empty()) {
      if (take_pending_line() && execute_line(out)) {
        if (modal_call_) schedule_modal_call(out);
        count_handed_block(out);
        return true;
      }
      continue;
    }
    switch (pending_) {
      case PendingAction::None: break;
      case PendingAction::Call:
        pending_ = PendingAction::None;
        if (!pending_section_start_.empty())
          call_contour_section(std::exchange(pending_section_program_, {}), std::exchange(pending_section_start_, {}),
                               std::exchange(pending_section_end_, {}), pending_column_);
        else
          call_program(pending_call_, pending_passes_, pending_column_);
        break;
      case PendingAction::Return:
        pending_ = PendingAction::None;
        return_one_level();
        // RET(..., levels): the next level at once, unless a SAVE block must come between.
        if (pending_ == PendingAction::Return && pending_save_ == ModalSave::None) continue;
        break;
      case PendingAction::EndProgram:
        pending_ = PendingAction::None;
        frames_.clear();
        break;
    }
    if (frames_.empty()) return false;
    if (pending_save_ != ModalSave::None) {
      // A block of its own: the interpreter keeps or restores its modal state here.
      out.clear();
      out.modal_save = pending_save_;
      pending_save_ = ModalSave::None;
      out.file = frames_.back()->file;
      out.line = position_.line;
      out.program_level = static_cast<int>(frames_.size()) - 1;
      return true;
    }
    Frame& f = *frames_.back();
    if (!read_line(f)) {
      end_of_file();
      continue;
    }
    if (is_blank_or_comment(text_)) continue;  // empty, comment, tape header
    if (frames_.size() == 1) main_has_content_ = true;
    if (execute_line(out)) {
      if (modal_call_) schedule_modal_call(out);
      count_handed_block(out);
      return true;
    }
  }
}

void ProgramLoader::count_handed_block(const Block& out) {
  // A program stop (M0, M1) waits for the operator as G4 waits for the clock: a loop around it
  // whose exit reads an input (`L: M0 / IF $A_IN[10]==0 GOTOB L`) is a wait, not work.
  const bool only_stops = !out.m.empty() && out.axis_words.empty() && !out.find_address("S") &&
                          std::all_of(out.m.begin(), out.m.end(), [](const auto& m) {
                            return m.extension < 0 && (m.code == 0 || m.code == 1);
                          });
  if (out.has_g(4) || only_stops) ++dwell_blocks_;
  else if (!out.axis_words.empty() || !out.m.empty() || out.find_address("S")) ++work_blocks_;
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
      case Statement::Extern: return false;  // a declaration: calls find the program anyway
      case Statement::Define:
        define_macro(parsed_.call_name, trimmed(parsed_.macro_text));
        return false;
      case Statement::SyncAction:
      case Statement::Interrupt:
        f.executed_block = true;
        sync_actions_seen_ = true;
        note_sync_action_targets();
        warn_not_modelled(parsed_.statement == Statement::SyncAction ? "synchronized action (" + std::string(parsed_.call_name) + ")"
                                                                     : std::string(parsed_.call_name),
                          parsed_.statement_column);
        return false;
      case Statement::Call: {
        uint64_t passes = 1;
        if (!parsed_.items.empty()) passes = static_cast<uint64_t>(parsed_.items.front().code);
        f.executed_block = true;
        pending_args_.clear();
        // CALL takes the program name from a STRING variable when one has that name
        // (PGA Job Planning, "Indirect subprogram call (CALL)").
        std::string name(parsed_.call_name);
        if (parsed_.target.expr != kNoExpr) {
          const Value v = eval_value(parsed_.target.expr);
          if (!v.is_text()) throw LineError(12150, parsed_.target.column, "CALL needs a program name as a string");
          name = v.text;
        } else if (const Variable* v = find_variable(name); v && v->type() == DataType::String && v->rank() == 0)
          name = v->get(v->element({}, parsed_.target.column)).text;
        // The section's labels are read in the caller (they may be its STRING variables).
        const bool section = !parsed_.section_label.empty();
        const std::string start_label = section ? section_label(parsed_.section_label) : std::string();
        const std::string end_label = section ? section_label(parsed_.end_label) : std::string();
        const size_t levels = frames_.size();
        call_program(name, passes, parsed_.target.column);
        if (section && frames_.size() > levels) run_program_section(start_label, end_label, parsed_.target.column);
        return false;
      }
      case Statement::Goto:
        f.executed_block = true;
        jump(parsed_.jump, parsed_.target);
        return false;
      case Statement::IfGoto:
        f.executed_block = true;
        execute_if_goto();
        return false;
      case Statement::Case:
        f.executed_block = true;
        execute_case();
        return false;
      case Statement::RepeatSection:
        f.executed_block = true;
        execute_repeat_section();
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
  warn(990002, std::string(name), column);
}

bool ProgramLoader::has_program(std::string_view name) const {
  return files_->find(normalize_program_name(name)).has_value();
}

void ProgramLoader::warn(int number, const std::string& text, uint32_t column) {
  if (warned_.size() >= kMaxWarnings || frames_.empty()) return;
  // One warning per text and line: a loop must not print it a million times.
  std::string key = std::to_string(number) + text + '@' + *frames_.back()->file + ':' + std::to_string(position_.line);
  if (!warned_.insert(std::move(key)).second) return;
  diagnostics_.warn(number, text, SourceLocation{*frames_.back()->file, position_.line, column},
                    std::string(trimmed(text_)));
}

void ProgramLoader::call_program(const std::string& written_name, uint64_t passes, uint32_t column) {
  if (static_cast<int>(frames_.size()) > kMaxProgramLevel)
    raise(990003, "calling " + written_name, column);
  const ProgramName name = normalize_program_name(written_name);
  const auto path = files_->find(name);
  if (!path && call_archived_program(name, passes)) return;
  if (!path) {
    const std::string_view guess = near_miss(name.name);
    if (!guess.empty())
      raise(12550, "name " + name.name + " not defined (did you mean " + std::string(guess) + "?)", column);
    if (options_.missing_programs_warn) {
      // The user has no copy of it (a machine builder's cycle): go on as if it returned at once.
      if (missing_programs_.insert(name.name).second)
        warn(14011, "program " + name.name + " not found in the search path: call skipped", column);
      pending_args_.clear();
      return;
    }
    raise(14011, "program " + name.name + " not found in the search path", column);
  }
  auto frame = std::make_unique<Frame>();
  if (!frame->reader.open(*path)) raise(990005, path->string(), column);
  start_at_own_header(*frame);
  frame->file = intern_file_name(path->string());
  push_called_frame(std::move(frame), name.name, passes);
}

bool ProgramLoader::call_archived_program(const ProgramName& name, uint64_t passes) {
  // Not a file of its own: a section of an archive file already open (the main program and its
  // subprograms in one punched-tape file). Looked for once per name, innermost program first.
  const std::string key = name.name + "." + name.extension;
  auto it = archived_programs_.find(key);
  if (it == archived_programs_.end()) {
    std::optional<ArchivedProgram> hit;
    for (auto f = frames_.rbegin(); f != frames_.rend() && !hit; ++f)
      if (auto section = find_archive_section(std::filesystem::path(*(*f)->file), name))
        hit = ArchivedProgram{(*f)->file, *section};
    it = archived_programs_.emplace(key, std::move(hit)).first;
  }
  if (!it->second) return false;
  const ArchivedProgram& a = *it->second;
  auto frame = std::make_unique<Frame>();
  if (!frame->reader.open(*a.file)) return false;
  frame->reader.seek(a.section.start);
  frame->reader.set_end(a.section.end);
  frame->start = a.section.start;
  frame->file = a.file;
  push_called_frame(std::move(frame), name.name, passes);
  return true;
}

void ProgramLoader::call_contour_section(const std::string& program, const std::string& start_label,
                                         const std::string& end_label, uint32_t column) {
  if (static_cast<int>(frames_.size()) > kMaxProgramLevel) raise(990003, "calling " + start_label, column);
  // A program already running (the caller, or PROG further out) is read again from its start
  // (in an archive file: its section), as CALL "PROG" BLOCK start TO end reads PROG; another PROG
  // is called by name.
  const Frame* source = frames_.size() >= 2 ? frames_[frames_.size() - 2].get() : frames_.front().get();
  if (!program.empty()) {
    source = nullptr;
    for (auto f = frames_.rbegin(); f != frames_.rend() && !source; ++f)
      if ((*f)->program == program) source = f->get();
  }
  if (source) {
    auto frame = std::make_unique<Frame>();
    if (!frame->reader.open(*source->file)) raise(990005, *source->file, column);
    frame->reader.seek(source->start);
    frame->start = source->start;
    frame->file = source->file;
    const std::string name = source->program;
    push_called_frame(std::move(frame), name, 1);
  } else {
    const size_t levels = frames_.size();
    call_program(program, 1, column);
    if (frames_.size() == levels) return;  // not found, and only warned (--missing-programs warn)
  }
  try {
    run_program_section(start_label, end_label, column);
  } catch (const LineError& e) {  // a label not found: 14080 at the calling block
    frames_.pop_back();
    raise(e.number(), e.detail(), e.column());
  }
}

void ProgramLoader::push_called_frame(std::unique_ptr<Frame> frame, const std::string& program, uint64_t passes) {
  frame->program = program;
  frame->passes_left = std::max<uint64_t>(1, passes);
  frame->args = std::move(pending_args_);
  pending_args_.clear();
  frame->modal_call = pending_is_modal_call_;
  pending_is_modal_call_ = false;
  if (std::find(programs_used_.begin(), programs_used_.end(), program) == programs_used_.end())
    programs_used_.push_back(program);
  frames_.push_back(std::move(frame));
}

namespace {

// Axis words that are values, not a motion: a pole (G110..G112), an axial offset (G58/G59), a
// working-area limit (G25/G26) or a frame statement takes them (Fundamentals: each stands in a
// block of its own), so such a block calls no MCALL (before 2026-11-28 a polar bolt circle's
// G111 or an ATRANS drilled the last hole again).
bool axis_words_are_values(const Block& block) {
  for (const GWord& g : block.g)
    if (g.code == 110 || g.code == 111 || g.code == 112 || g.code == 58 || g.code == 59 || g.code == 25 ||
        g.code == 26)
      return true;
  static constexpr std::string_view kFrameStatements[] = {"TRANS", "ATRANS", "ROT",    "AROT",    "ROTS",
                                                           "AROTS", "SCALE",  "ASCALE", "MIRROR", "AMIRROR"};
  for (const CommandWord& c : block.commands)
    if (std::find(std::begin(kFrameStatements), std::end(kFrameStatements), c.name) != std::end(kFrameStatements))
      return true;
  return false;
}

}  // namespace

void ProgramLoader::schedule_modal_call(const Block& block) {
  if (pending_ != PendingAction::None) return;  // the block calls or ends itself
  for (const auto& f : frames_)
    if (f->modal_call) return;
  if (axis_words_are_values(block)) return;
  const bool moves = std::any_of(block.addresses.begin(), block.addresses.end(), [](const AddressWord& a) {
    const std::string_view n = a.name;
    if (n == "AP" || n == "RP") return true;
    if (n.empty() || std::string_view("XYZABCUVW").find(n[0]) == std::string_view::npos) return false;
    return std::all_of(n.begin() + 1, n.end(), [](char c) { return c >= '0' && c <= '9'; });
  });
  if (!moves) return;
  pending_ = PendingAction::Call;
  pending_call_ = modal_call_->name;
  pending_passes_ = 1;
  pending_column_ = modal_call_->column;
  pending_args_ = modal_call_->args;
  pending_is_modal_call_ = true;
}

void ProgramLoader::end_of_file() {
  Frame& f = *frames_.back();
  if (!f.control.empty()) {
    const ControlFrame& open = f.control.back();
    position_ = open.head;
    text_.clear();
    raise(12640, std::string(statement_keyword(open.kind)) + " without " + statement_keyword(closer_of(open.kind)), 1);
  }
  if (frames_.size() == 1 && !main_has_content_) {
    position_ = LinePosition{0, 1};
    text_.clear();
    raise(990010, "", 1);
  }
  // The last block of a program carries its end (Fundamentals, "Structure and contents of an
  // NC program"): a main program that runs off its file was most often cut off in transfer.
  if (frames_.size() == 1) warn(990017, "the last block run is the end of the file", 1);
  finish_frame();
}

void ProgramLoader::return_one_level() {
  ReturnRequest& r = return_request_;
  if (return_levels_left_ == 0) return_levels_left_ = std::max(1, r.levels);
  const bool parameterised = r.target || r.levels > 1 || r.to_start;
  // A parameterised return ends the subprogram whatever passes P had left (drycut's reading).
  if (parameterised) frames_.back()->passes_left = 1;
  finish_frame();
  // Never past the main program: the levels end at it.
  if (--return_levels_left_ > 0 && frames_.size() > 1) {
    pending_ = PendingAction::Return;  // the next level after a SAVE block, if one is due
    return;
  }
  return_levels_left_ = 0;
  const ReturnRequest done = std::exchange(r, ReturnRequest{});
  if (frames_.empty()) return;
  if (done.to_start) {
    jump_to_start();
  } else if (done.target) {
    position_ = frames_.back()->reader.tell();  // the search starts at the call, in the caller
    jump_to_value(JumpDirection::ForwardThenBackward, *done.target, 0);
    if (done.after_target) {
      Frame& f = *frames_.back();
      f.reader.next(raw_);  // the target block itself is not run
    }
  }
}

void ProgramLoader::finish_frame() {
  Frame& f = *frames_.back();
  if (f.passes_left > 1) {  // next pass of a subprogram called with P
    --f.passes_left;
    f.control.clear();
    f.repeats.clear();
    f.locals.clear();
    f.executed_block = false;
    f.reader.seek(f.start);
    return;
  }
  if (f.save) pending_save_ = ModalSave::Restore;
  frames_.pop_back();
}

}  // namespace drycut::parser
