// `drycut language [--markdown]`: the NC language as drycut knows it, one row per statement,
// command, G code, function, address and system-variable class (docs/language.md is this output).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "parser/language_table.hpp"

namespace drycut::app {

void register_language(CLI::App& app) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("language", "List the NC language drycut knows and what it does with each part");
  cmd->add_flag("--markdown", *markdown, "Write docs/language.md (a Markdown table per section)");
  cmd->callback([markdown] {
    if (*markdown) {
      std::fputs(parser::language_markdown().c_str(), stdout);
    } else {
      for (const auto& f : parser::language_features())
        std::printf("%-18s %-40s %s\n", f.section.c_str(), f.name.c_str(), std::string(parser::support_text(f.support)).c_str());
    }
    throw ExitRequest{kExitOk};
  });
}

}  // namespace drycut::app
