#include "report/junit_writer.hpp"

#include <cstdio>

namespace drycut::report {

namespace {

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", s);
  return buf;
}

std::string failure_element(const JUnitCase& c) {
  std::string message = c.failures.front();
  if (c.failures.size() > 1) message += " (and " + std::to_string(c.failures.size() - 1) + " more)";
  std::string body;
  for (const auto& f : c.failures) body += xml_escape(f) + "\n";
  return "      <failure message=\"" + xml_escape(message) + "\" type=\"regression\">" + body + "</failure>\n";
}

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const unsigned char c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 allows tab, newline and carriage return of the C0 controls only.
        if (c >= 0x20 || ch == '\t' || ch == '\n' || ch == '\r') out += ch;
    }
  }
  return out;
}

std::string junit_xml(const std::string& suite_name, const std::vector<JUnitCase>& cases) {
  size_t failed = 0;
  double total_s = 0;
  for (const auto& c : cases) {
    failed += c.failures.empty() ? 0 : 1;
    total_s += c.time_s;
  }
  const std::string counts = " tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failed) +
                             "\" errors=\"0\" skipped=\"0\" time=\"" + seconds(total_s) + "\"";
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuites name=\"" + xml_escape(suite_name) + "\"" + counts + ">\n";
  xml += "  <testsuite name=\"" + xml_escape(suite_name) + "\"" + counts + ">\n";
  for (const auto& c : cases) {
    xml += "    <testcase name=\"" + xml_escape(c.name) + "\" classname=\"" + xml_escape(c.classname) + "\" time=\"" +
           seconds(c.time_s) + "\"";
    if (c.failures.empty()) {
      xml += "/>\n";
      continue;
    }
    xml += ">\n" + failure_element(c) + "    </testcase>\n";
  }
  xml += "  </testsuite>\n</testsuites>\n";
  return xml;
}

}  // namespace drycut::report
