#pragma once
// JUnit XML, the test-report format GitLab (artifacts:reports:junit), Jenkins (junit step) and
// GitHub actions (test-reporter and the like) read: one <testsuite> in a <testsuites> root, one
// <testcase name classname time> per test, a <failure message type> child for a failed one
// (message: one line; the element's text: the details, one per line).
#include <string>
#include <vector>

namespace drycut::report {

struct JUnitCase {
  std::string name;       // e.g. the program's path relative to the baseline
  std::string classname;  // dotted group, e.g. "drycut.regress.thesis"
  double time_s = 0;      // wall time spent on it
  std::vector<std::string> failures;  // empty: passed
};

std::string junit_xml(const std::string& suite_name, const std::vector<JUnitCase>& cases);

// Text with &, <, >, " and ' escaped, and characters XML 1.0 does not allow dropped.
std::string xml_escape(const std::string& text);

}  // namespace drycut::report
