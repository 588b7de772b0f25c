#include "report/html_escape.hpp"

#include <gtest/gtest.h>

namespace drycut::report {
namespace {

TEST(HtmlEscape, ReplacesMarkupCharacters) {
  EXPECT_EQ(html_escape("<script>alert(\"x\")</script> & 'y'"),
            "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt; &amp; &#39;y&#39;");
}

TEST(HtmlEscape, LeavesPlainTextAndUtf8Alone) {
  EXPECT_EQ(html_escape("N10 G1 X22.000 Y0 F1000 ; Fräsen"), "N10 G1 X22.000 Y0 F1000 ; Fräsen");
  EXPECT_EQ(html_escape(""), "");
}

TEST(HtmlEscape, ReplacesNulBytes) {
  const std::string with_nul("a\0b", 3);
  EXPECT_EQ(html_escape(with_nul), "a&#xFFFD;b");
}

}  // namespace
}  // namespace drycut::report
