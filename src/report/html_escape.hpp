#pragma once
// Text from part programs (block text, alarm text, file names) goes into the HTML report; it may
// contain <, >, & and quotes, so everything is escaped before it reaches the page.
#include <string>
#include <string_view>

namespace drycut::report {

// Replaces & < > " ' by character references; other bytes pass unchanged.
std::string html_escape(std::string_view text);

}  // namespace drycut::report
