#include "parser/program_files.hpp"

#include <system_error>

#include "parser/ascii_case.hpp"

namespace drycut::parser {
namespace {

bool ends_with(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

}  // namespace

ProgramName normalize_program_name(std::string_view written) {
  ProgramName p;
  // A path as the control writes it ("/_N_SPF_DIR/_N_SUB_SPF", "/_N_WKS_DIR/_N_PART_WPD/..."):
  // drycut's folders take the place of the control's directories, so only the name counts.
  if (const size_t slash = written.find_last_of("/\\"); slash != std::string_view::npos)
    written = written.substr(slash + 1);
  std::string s = upper_ascii(written);
  if (ends_with(s, ".SPF") || ends_with(s, ".MPF")) {
    p.extension = s.substr(s.size() - 3);
    s.resize(s.size() - 4);
  }
  if (s.size() > 7 && s.rfind("_N_", 0) == 0 && (ends_with(s, "_SPF") || ends_with(s, "_MPF"))) {
    p.extension = s.substr(s.size() - 3);
    s = s.substr(3, s.size() - 7);
  }
  p.name = std::move(s);
  return p;
}

ProgramFiles::ProgramFiles(std::vector<std::filesystem::path> directories)
    : directories_(std::move(directories)), listings_(directories_.size()) {}

const std::unordered_map<std::string, std::filesystem::path>& ProgramFiles::listing(size_t d) {
  if (!listings_[d]) {
    listings_[d].emplace();
    std::error_code ec;
    for (std::filesystem::directory_iterator it(directories_[d], ec), end; !ec && it != end; it.increment(ec)) {
      std::error_code file_ec;
      if (!it->is_regular_file(file_ec)) continue;
      // The first spelling wins if a folder holds both SUB.SPF and sub.spf.
      listings_[d]->emplace(upper_ascii(it->path().filename().string()), it->path());
    }
  }
  return *listings_[d];
}

std::optional<std::filesystem::path> ProgramFiles::find(const ProgramName& program) {
  std::vector<std::string> candidates;
  const std::string& n = program.name;
  for (const std::string_view ext : {std::string_view("SPF"), std::string_view("MPF")}) {
    if (!program.extension.empty() && program.extension != ext) continue;
    const std::string e(ext);
    candidates.push_back(n + "." + e);
    candidates.push_back("_N_" + n + "_" + e + "." + e);
    candidates.push_back("_N_" + n + "_" + e);
  }
  if (program.extension.empty()) candidates.push_back(n);  // a file without extension
  for (size_t d = 0; d < directories_.size(); ++d) {
    const auto& files = listing(d);
    for (const auto& c : candidates)
      if (auto it = files.find(c); it != files.end()) return it->second;
  }
  // The extension attached with "_" ("SUB_SPF" for SUB.SPF; Function Manual K1, "Executing from
  // external source": "_" or "." may attach it), when no program has the whole name.
  if (program.extension.empty() && n.size() > 4 && (ends_with(n, "_SPF") || ends_with(n, "_MPF")))
    return find(ProgramName{n.substr(0, n.size() - 4), n.substr(n.size() - 3)});
  // The prefix without the extension ("_N_SUB" for SUB; Programming Manual: prefix, name and
  // extension may be combined in a call), when no program has the whole name.
  if (n.size() > 3 && n.rfind("_N_", 0) == 0) return find(ProgramName{n.substr(3), program.extension});
  return std::nullopt;
}

std::optional<ArchiveSection> find_archive_section(const std::filesystem::path& file, const ProgramName& program) {
  LineReader reader;
  if (!reader.open(file)) return std::nullopt;
  std::optional<ArchiveSection> found[2];  // SPF, MPF
  std::optional<ArchiveSection>* open = nullptr;  // the section being read: ends at the next header
  RawLine raw;
  while (reader.next(raw)) {
    std::string_view t = raw.bytes;
    while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
    // Only a program header ("%_N_...") begins a program; a bare "%" (a tape leader) does not.
    if (t.size() < 5 || t[0] != '%' || t[1] != '_' || (t[2] != 'N' && t[2] != 'n') || t[3] != '_') continue;
    if (open) {
      (*open)->end = raw.position.offset;
      open = nullptr;
    }
    while (!t.empty() && (t.back() == ' ' || t.back() == '\t' || t.back() == '\r')) t.remove_suffix(1);
    const ProgramName header = normalize_program_name(t.substr(1));
    if (header.name != program.name || header.extension.empty()) continue;
    if (!program.extension.empty() && header.extension != program.extension) continue;
    auto& slot = found[header.extension == "SPF" ? 0 : 1];
    if (slot) continue;  // the first one of a name counts
    slot = ArchiveSection{reader.tell(), UINT64_MAX};
    open = &slot;
  }
  return found[0] ? found[0] : found[1];
}

}  // namespace drycut::parser
