#pragma once
// Finds subprogram files along the search path. Program names are case-insensitive on the
// control, so file names are matched case-insensitively on disk too (EKVI_POSTUPNE_45.SPF and
// ekvi_postupne_45.spf are the same program).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "parser/line_reader.hpp"

namespace drycut::parser {

// "_N_SUB_SPF", "sub.spf", "SUB", "/_N_SPF_DIR/_N_SUB_SPF" -> name "SUB", extension "SPF" / ""
// (none given); a directory in front is dropped.
struct ProgramName {
  std::string name;       // upper case
  std::string extension;  // "SPF", "MPF" or empty
};
ProgramName normalize_program_name(std::string_view written);

// A program inside an archive file (punched-tape format: several programs one after the other,
// each starting with its header line %_N_NAME_MPF / %_N_NAME_SPF, as the control's data backup and
// many DNC transfers write them): its first line after the header, and the offset where the next
// header begins (UINT64_MAX: the file's end).
struct ArchiveSection {
  LinePosition start;
  uint64_t end = UINT64_MAX;
};
// The section of `program` in `file`, if the file holds one (SPF before MPF unless the extension
// was given). Reads the whole file: callers keep the answer.
std::optional<ArchiveSection> find_archive_section(const std::filesystem::path& file, const ProgramName& program);

class ProgramFiles {
 public:
  explicit ProgramFiles(std::vector<std::filesystem::path> directories);
  // First directory wins; within it SPF before MPF unless the extension was given.
  std::optional<std::filesystem::path> find(const ProgramName& program);

 private:
  const std::unordered_map<std::string, std::filesystem::path>& listing(size_t directory);

  std::vector<std::filesystem::path> directories_;
  // Upper-case file name -> path, per directory, read once.
  std::vector<std::optional<std::unordered_map<std::string, std::filesystem::path>>> listings_;
};

}  // namespace drycut::parser
