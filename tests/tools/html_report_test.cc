#include "tools/eval/html_report.h"

#include <gtest/gtest.h>

#include "tests/evaluation/eval_test_records.h"

namespace corridor {
namespace {

using testing_util::Frames;

TEST(HtmlReport, StaticPageWithTablesPlotsAndRelativeImages) {
  std::vector<FrameRecord> frames = Frames();
  frames[0].frame = "a b<1>";
  ReportContext context;
  context.dataset = "<data>";
  context.plot_files = {"plots/abs_rel_by_depth.png"};
  const std::string html =
      ReportHtml({BuildReport(frames, {1.5, 2.0}, "grid", "paper")}, context, true);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<meta charset=\"utf-8\">"), std::string::npos);
  EXPECT_NE(html.find("<h2 id=\"table1\">Table 1: Accuracy of corridor width estimation</h2>"),
            std::string::npos);
  EXPECT_NE(html.find("<h2 id=\"table3\">"), std::string::npos);
  EXPECT_NE(html.find("<tr class=\"summary\"><td class=\"text\">all</td><td>0.23333</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<img src=\"plots/abs_rel_by_depth.png\""), std::string::npos);
  EXPECT_NE(html.find("src=\"vis/Cord_E01/001.png\""), std::string::npos);
  EXPECT_NE(html.find("src=\"vis/Cord_E01/a%20b%3C1%3E.png\""), std::string::npos);
  EXPECT_NE(html.find("&lt;data&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<data>"), std::string::npos);
  EXPECT_NE(html.find("class=\"failed\""), std::string::npos);
  // Nothing external: no scripts, no absolute links.
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("http:"), std::string::npos);
  EXPECT_EQ(html.find("https:"), std::string::npos);
  EXPECT_EQ(html.find("src=\"/"), std::string::npos);
}

TEST(HtmlReport, WithoutVisHasNoFrameSection) {
  const std::string html =
      ReportHtml({BuildReport(Frames(), {1.5, 2.0}, "grid", "paper")}, {}, false);
  EXPECT_EQ(html.find("vis/"), std::string::npos);
  EXPECT_NE(html.find("</html>"), std::string::npos);
}

TEST(HtmlReport, Escaping) {
  EXPECT_EQ(HtmlEscape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(UrlPath("vis/x y/f#1.png"), "vis/x%20y/f%231.png");
}

}  // namespace
}  // namespace corridor
