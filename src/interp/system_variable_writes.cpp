// `$` system variables the program writes and the interpreter models: tool data $TC_DP3
// (length) and $TC_DP6 (radius) of tool t, edge d. Frame variables ($P_UIFR, $P_PFRAME) are
// accepted: their FRAME values are not computed (docs/language.md), so they warn. Other writes
// were kept by the loader (later reads see them) and change nothing drycut times.
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

#include <cstdlib>

namespace drycut::interp {

using detail::kNotModelled;

void Interpreter::apply_system_writes(const parser::Block& block) {
  for (const parser::SystemWrite& w : block.system_writes) {
    const SourceLocation where{block.file ? *block.file : std::string(), block.line, w.column};
    if (w.name.rfind("$TC_DP", 0) == 0 && w.indices.size() == 2 && w.indices[0].is_number() &&
        w.indices[1].is_number() && w.value.is_number()) {
      const int parameter = std::atoi(w.name.c_str() + 6);
      // Indices no int holds are outside the table like any other (and their cast undefined).
      auto index = [](double v) { return v > -2147483648.0 && v < 2147483648.0 ? static_cast<int>(v) : -1; };
      if (!tools_.set_edge_parameter(parameter, index(w.indices[0].number), index(w.indices[1].number),
                                     w.value.number))
        diagnostics_.warn(kNotModelled, w.name + ": index outside the tool table's range", where, block.text);
      continue;
    }
    if ((w.name == "$P_UIFR" || w.name == "$P_PFRAME" || w.name == "$P_BFRAME") && warned_.insert(w.name).second)
      diagnostics_.warn(kNotModelled, w.name + " written: FRAME values are not computed, the frame stays as it was",
                        where, block.text);
  }
}

}  // namespace drycut::interp
