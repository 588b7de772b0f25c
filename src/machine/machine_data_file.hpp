#pragma once
// Machine data as the control writes it to text: MD files (INI/TEA form, e.g. _N_NC_TEA,
// _N_CH1_TEA, _N_AX1_TEA, INITIAL.INI) and the same lines inside an archive in punched-tape
// format. docs/machine-data-import.md describes the format and its sources.
//
// One assignment per line:  [Nnnnnn] $MA_MAX_AX_VELO[AX1]=30000 ['xxxx] [; comment]
//   - an optional MD number as block number (N32000) and an optional line checksum after a
//     blank and an apostrophe (MD11230 MD_FILE_STYLE) are skipped;
//   - the index list holds array indices and/or an axis (AX1 or the machine axis name X1);
//   - values: numbers, 'H3F' (hex), 'B101' (binary), "text", TRUE/FALSE;
//   - CHANDATA(n) makes the following $MC_ (and $SC_) lines belong to channel n;
//   - %file headers, ;$PATH= lines, comments, M17/M30 and empty lines are structure, not data.
// Any other line is kept as "not understood" with its file:line (reported, never fatal).
#include <string>
#include <variant>
#include <vector>

namespace drycut::machine {

struct MachineDatum {
  std::string area;                // "MN", "MC", "MA", "SN", "SC", "SA", ... (upper case)
  std::string name;                // "MAX_AX_VELO" (upper case, without $M?_)
  std::vector<std::string> index;  // ["0", "AX1"], upper case; empty when not indexed
  std::variant<double, std::string> value;
  int channel = 1;   // CHANDATA(n) in force (1 before any CHANDATA)
  std::string file;  // as given on the command line
  int line = 0;

  std::string location() const { return file + ":" + std::to_string(line); }
  // "$MA_MAX_AX_VELO" (without the index).
  std::string full_name() const { return "$" + area + "_" + name; }
};

struct MachineDataText {
  std::vector<MachineDatum> data;
  std::vector<std::string> not_understood;  // "file:line: text"
};

// Parses the text of one file; appends to `out`. Never throws on bad lines.
void parse_machine_data_text(const std::string& text, const std::string& file, MachineDataText& out);
// Reads and parses one file; throws std::runtime_error when it cannot be opened.
void read_machine_data_file(const std::string& path, MachineDataText& out);

}  // namespace drycut::machine
