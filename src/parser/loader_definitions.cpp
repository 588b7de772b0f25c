// Definitions in the loader: DEF (local variables, before the first executable block, alarm
// 14500 after it), PROC parameters (by value, or VAR by reference), definition files
// (GUD: DEF NCK/CHAN; MAC: DEFINE name AS text) and macro expansion.
#include <algorithm>
#include <cmath>

#include "parser/ascii_case.hpp"
#include "parser/line_error.hpp"
#include "parser/loader_frame.hpp"
#include "parser/text_decoding.hpp"

namespace drycut::parser {

namespace {

constexpr double kMaxArrayElements = 1e6;

bool is_name_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '$';
}

// DEFINE name AS text, after an optional block number: where the name starts (npos for any
// other line). The name is taken as written, the text may use earlier macros.
size_t defined_name_start(std::string_view line) {
  size_t i = line.find_first_not_of(" \t");
  if (i != std::string_view::npos && (line[i] == 'N' || line[i] == 'n')) {
    const size_t digits = line.find_first_not_of("0123456789", i + 1);
    if (digits != i + 1) i = line.find_first_not_of(" \t", digits);
  }
  if (i == std::string_view::npos || line.size() - i < 7) return std::string_view::npos;
  for (size_t k = 0; k < 6; ++k)
    if ((line[i + k] & ~0x20) != "DEFINE"[k]) return std::string_view::npos;
  if (is_name_char(line[i + 6])) return std::string_view::npos;
  return line.find_first_not_of(" \t", i + 6);
}

// NAME.DEF as drycut and the control's editor name them, or the control's own file name
// _N_NAME_DEF (`_N_UGUD_DEF`, `_N_SMAC_DEF`) as an archive or a copy of the NC's data holds it.
bool is_definition_file_name(const std::string& file_name) {
  const std::string name = upper_ascii(file_name);
  return name.ends_with(".DEF") || (name.starts_with("_N_") && name.ends_with("_DEF") && name.size() > 7);
}

}  // namespace

Variable ProgramLoader::make_variable(const DefEntry& d) {
  DataType type = DataType::Real;
  parse_data_type(d.type, type);
  std::vector<uint32_t> dims;
  double elements = 1;
  for (uint8_t k = 0; k < d.rank; ++k) {
    if (d.dims[k] == kNoExpr) throw LineError(12080, d.column, "array " + std::string(d.name) + " needs its size");
    const double n = eval(d.dims[k]);
    if (!(n >= 1) || n != std::trunc(n)) throw LineError(12160, d.column, "array size must be a whole number >= 1");
    elements *= n;
    if (elements > kMaxArrayElements) throw LineError(12160, d.column, "array larger than 1,000,000 elements");
    dims.push_back(static_cast<uint32_t>(n));
  }
  return Variable(std::string(d.name), type, d.string_length ? d.string_length : 400, dims);
}

void ProgramLoader::initialise(Variable& v, const DefEntry& d) {
  v.reset();
  switch (d.init_kind) {
    case InitKind::None: return;
    case InitKind::Single:
      if (v.rank() > 0) {  // DEF REAL A[3]=5: every element
        const Value x = eval_value(d.init);
        for (size_t i = 0; i < v.size(); ++i) v.set(i, x, d.column);
      } else {
        v.set(0, eval_value(d.init), d.column);
      }
      return;
    case InitKind::Rep: {
      const Value x = eval_value(d.init);
      for (size_t i = 0; i < v.size(); ++i) v.set(i, x, d.column);
      return;
    }
    case InitKind::List:
      if (d.init_count > v.size())
        throw LineError(14130, d.column, std::to_string(d.init_count) + " values for " + std::to_string(v.size()) + " elements");
      for (uint32_t i = 0; i < d.init_count; ++i) v.set(i, eval_value(parsed_.pool.args[d.init_first + i]), d.column);
      return;
  }
}

void ProgramLoader::execute_def(bool from_definition_file) {
  Frame& f = *frames_.back();
  if (f.executed_block)
    throw LineError(14500, parsed_.statement_column, "DEF after the first executable block");
  const bool global = !parsed_.def_scope.empty();
  VariableTable& table = global ? globals_ : f.locals;
  for (const DefEntry& d : parsed_.defs) {
    Variable* existing = table.find(d.name);
    if (existing && from_definition_file && existing->standard_definition) {
      *existing = make_variable(d);  // in place: the table's addresses stay valid
      existing->def_line = position_.line;
    } else if (existing && (from_definition_file || existing->def_line != position_.line))
      throw LineError(12170, d.column, "name " + std::string(d.name) + " defined twice");
    if (!existing) {
      existing = &table.add(make_variable(d));
      existing->def_line = position_.line;
      existing->standard_definition = reading_standard_definitions_;
    }
    existing->stop_on_read = parsed_.def_stop_on_read;
    existing->stop_on_write = parsed_.def_stop_on_write;
    if (parsed_.def_lower_limit != kNoExpr) existing->lower_limit = eval(parsed_.def_lower_limit);
    if (parsed_.def_upper_limit != kNoExpr) existing->upper_limit = eval(parsed_.def_upper_limit);
    initialise(*existing, d);
  }
}

void ProgramLoader::execute_proc() {
  // Binds the call's arguments to the parameters: by value (converted to the parameter's type),
  // or VAR by reference (the parameter aliases the caller's variable, element or R parameter).
  Frame& f = *frames_.back();
  if (parsed_.proc_save && !f.save && frames_.size() > 1) {
    f.save = true;
    pending_save_ = ModalSave::Save;  // before the first block of the subprogram
  }
  if (f.args.size() > parsed_.defs.size())  // reported at the PROC line, where they are bound
    throw LineError(12340, parsed_.statement_column, std::to_string(f.args.size()) + " arguments for " +
                                                         std::to_string(parsed_.defs.size()) + " parameters");
  for (size_t i = 0; i < parsed_.defs.size(); ++i) {
    const DefEntry& d = parsed_.defs[i];
    if (f.locals.find(d.name)) continue;  // a new pass binds again only what is new
    DefEntry shape = d;
    for (auto& dim : shape.dims) dim = kNoExpr;
    const CallArgument* a = i < f.args.size() && f.args[i].given ? &f.args[i] : nullptr;
    std::vector<uint32_t> dims;
    if (d.rank > 0) {
      if (!(a && a->variable && a->element == SIZE_MAX))
        throw LineError(12410, d.column, "array parameter " + std::string(d.name) + " needs an array (VAR)");
      for (int k = 0; k < a->variable->rank(); ++k) dims.push_back(a->variable->dim(k));
    }
    DataType type = DataType::Real;
    parse_data_type(d.type, type);
    Variable& v = f.locals.add(Variable(std::string(d.name), type, d.string_length ? d.string_length : 400, dims));
    v.def_line = position_.line;
    if (!a) continue;
    if (d.by_reference) {
      if (a->r_parameter) v.alias_number(a->r_parameter);
      else if (a->variable) v.alias(a->variable, a->element == SIZE_MAX ? 0 : a->element);
      else v.set(0, a->value, d.column);  // a value where a reference is possible: a copy
    } else if (d.rank > 0) {
      // An array by value: the subprogram gets a copy of the caller's elements (its writes stay
      // local); before 2026-11-27 it got zeros, silently.
      for (size_t e = 0; e < v.size(); ++e) v.set(e, a->variable->get(e), d.column);
    } else {
      v.set(0, a->value, d.column);
    }
  }
}

void ProgramLoader::read_definition_files(const std::filesystem::path& main_folder) {
  std::vector<std::filesystem::path> dirs = options_.definition_dirs;
  dirs.push_back(main_folder);
  std::vector<std::filesystem::path> read;  // a folder named twice (--definitions . beside the program) is read once
  for (size_t k = 0; k < dirs.size(); ++k) {
    const std::filesystem::path& dir = dirs[k];
    reading_standard_definitions_ = k < options_.standard_definition_dirs;
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(dir, ec);
    if (std::find(read.begin(), read.end(), canonical) != read.end()) continue;
    read.push_back(canonical);
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_regular_file(dir, ec)) {
      files.push_back(dir);  // --definitions UGUD.DEF: that file, whatever its name
    } else {
      for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (is_definition_file_name(entry.path().filename().string()) && entry.is_regular_file(ec))
          files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& file : files) read_definition_file(file);
  }
  reading_standard_definitions_ = false;
}

void ProgramLoader::read_definition_file(const std::filesystem::path& file) {
  // A definition file holds DEF NCK/CHAN ... and DEFINE ... AS ... lines (plus M17/M30 and a
  // %_N_NAME_DEF header); everything else in it is ignored with a warning.
  auto frame = std::make_unique<Frame>();
  if (!frame->reader.open(file)) return;
  frame->file = intern_file_name(file.string());
  frames_.push_back(std::move(frame));
  Frame& f = *frames_.back();
  while (f.reader.next(raw_)) {
    position_ = raw_.position;
    if (raw_.too_long) continue;
    decode_line_to_utf8(raw_.bytes, text_);
    if (!macros_.empty() && may_hold_macro()) expand_macros();
    if (is_blank_or_comment(text_)) continue;
    try {
      parser_.parse(text_, parsed_);
      if (parsed_.statement == Statement::Def) {
        if (parsed_.def_scope.empty()) parsed_.def_scope = "CHAN";  // a DEF in a GUD file is global
        execute_def(true);
      } else if (parsed_.statement == Statement::Define) {
        define_macro(parsed_.call_name, trimmed(parsed_.macro_text));
      } else if (parsed_.statement == Statement::Extern) {
        // EXTERN and REDEF declare; REDEF's attributes change nothing drycut computes.
      } else if (!(parsed_.statement == Statement::Words && parsed_.items.size() == 1 &&
                   parsed_.items[0].kind == ItemKind::M)) {
        warn(990002, "only DEF and DEFINE are read from a definition file", 1);
      }
    } catch (const LineError& e) {
      raise(e.number(), e.detail(), e.column());  // names the definition file (its frame is on top)
    }
  }
  frames_.pop_back();
}

void ProgramLoader::define_macro(std::string_view name, std::string_view text) {
  macros_.insert_or_assign(std::string(name), std::string(text));
  if (name.empty()) return;
  const char c = name.front();
  for (const char k : {c, static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c),
                       static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c)}) {
    if (macro_initials_[static_cast<unsigned char>(k)]) continue;
    macro_initials_[static_cast<unsigned char>(k)] = true;
    macro_initial_list_ += k;
  }
}

bool ProgramLoader::may_hold_macro() const {
  // Every block passes here once macros exist (drycut's own cycle macros always do), so the
  // common block without any name that starts like a macro name costs one scan, no copy.
  if (macro_initial_list_.size() <= 4) {
    // Few initials (drycut's own macros all start with '_'): memchr per initial.
    const std::string_view line(text_.data(), std::min(text_.size(), text_.find(';')));
    for (const char c : macro_initial_list_)
      for (size_t k = line.find(c); k != std::string_view::npos; k = line.find(c, k + 1))
        if (k == 0 || !is_name_char(line[k - 1])) return true;
    return false;
  }
  for (size_t k = 0; k < text_.size(); ++k) {
    const char c = text_[k];
    if (c == ';') return false;
    if (macro_initials_[static_cast<unsigned char>(c)] && (k == 0 || !is_name_char(text_[k - 1]))) return true;
  }
  return false;
}

void ProgramLoader::expand_macros() {
  // Whole names outside strings and comments are replaced by their macro text (once: a macro's
  // text is not expanded again, so a macro cannot recurse). The name a DEFINE line defines is
  // taken as written: a machine's own macro file defines names drycut's CYCLE_MACROS.DEF defined
  // before it; its text may use earlier macros (expanded once, here).
  const size_t defined_name = defined_name_start(text_);
  std::string out;
  out.reserve(text_.size() + 16);
  bool changed = false;
  size_t i = 0;
  while (i < text_.size()) {
    const char c = text_[i];
    if (c == ';') break;
    if (c == '"') {
      const size_t close = text_.find('"', i + 1);
      const size_t end = close == std::string::npos ? text_.size() : close + 1;
      out.append(text_, i, end - i);
      i = end;
      continue;
    }
    if (is_name_char(c) && !(c >= '0' && c <= '9')) {
      size_t j = i;
      while (j < text_.size() && is_name_char(text_[j])) ++j;
      std::string word = text_.substr(i, j - i);
      for (char& w : word) w = static_cast<char>(w >= 'a' && w <= 'z' ? w - 'a' + 'A' : w);
      auto it = i == defined_name ? macros_.end() : macros_.find(word);
      if (it != macros_.end()) {
        // The expanded block obeys the block length limit too: a long macro used many times in
        // one line would otherwise grow it to gigabytes.
        if (out.size() + it->second.size() > LineReader::kMaxLineLength)
          raise(12080, "block longer than " + std::to_string(LineReader::kMaxLineLength) +
                           " characters after macro expansion", 1);
        out += it->second;
        changed = true;
      } else {
        out.append(text_, i, j - i);
      }
      i = j;
      continue;
    }
    out += c;
    ++i;
  }
  if (!changed) return;
  out.append(text_, i, std::string::npos);
  text_ = std::move(out);
}

}  // namespace drycut::parser
