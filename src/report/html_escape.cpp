#include "report/html_escape.hpp"

namespace drycut::report {

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      // NUL and other control bytes would make the page invalid: show them as a replacement mark.
      case '\0': out += "&#xFFFD;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace drycut::report
