#include "catena/io/report.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace catena::io {
namespace {

Report sample() {
  Report r;
  r.title = "Chain </script><script>alert(1)</script> & co";
  r.case_name = "case.toml";
  r.case_hash = std::string(64, 'a');
  r.version = "0.1.0";
  r.inputs.push_back({"chain.pitch", "125 mm", ""});
  ReportSection s;
  s.id = "hinge";
  s.title = "Hinge";
  s.source = "000 eq. (6)";
  s.diagnostics.push_back({"error", "σH > [σH]", "1.2e9 Pa"});
  s.tables.push_back({"Results", {{"R2", "35.4", "mm"}}});
  s.grids.push_back({"Designs", {"R1 [mm]", "ok"}, {{"1", "yes"}, {"2", "no"}}, {false, true}});
  ReportChart c;
  c.title = "dt </script>";
  c.traces.push_back({"dt", {0.0, 1.0, 2.0}, {0.0, NAN, 4.0}});
  s.charts.push_back(c);
  s.drawings_svg.push_back(
      "<?xml version=\"1.0\"?><svg><defs><g id=\"glyph0\"/></defs><use xlink:href=\"#glyph0\"/>"
      "<path clip-path=\"url(#clip1)\"/></svg>");
  s.drawings_svg.push_back("<svg><g id=\"glyph0\"/></svg>");
  r.sections.push_back(s);
  ReportSection failed;
  failed.id = "contact";
  failed.title = "Contact";
  failed.failure = "no data";
  r.sections.push_back(failed);
  return r;
}

TEST(Report, UserTextIsEscapedAndCannotCloseAScript) {
  const std::string html = to_html(sample(), "/*plotly*/");
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_NE(html.find("Chain &lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt; &amp; co"),
            std::string::npos);
  // in the chart data "<" is written \u003c: exactly the three script elements close
  std::size_t closes = 0;
  for (std::size_t at = html.find("</script>"); at != std::string::npos;
       at = html.find("</script>", at + 1))
    ++closes;
  EXPECT_EQ(closes, 3u);
  EXPECT_NE(html.find("dt \\u003c/script\\u003e"), std::string::npos);
}

TEST(Report, ChartDataGapsAndSectionsAreWritten) {
  const std::string html = to_html(sample(), "/*plotly*/");
  EXPECT_NE(html.find("\"y\":[0,null,4]"), std::string::npos);  // NaN becomes a gap
  EXPECT_NE(html.find("<div class=\"chart\" id=\"catena-chart-0\">"), std::string::npos);
  EXPECT_NE(html.find("<section id=\"hinge\" class=\"analysis\">"), std::string::npos);
  EXPECT_NE(html.find("class=\"diagnostic error\""), std::string::npos);
  EXPECT_NE(html.find("could not run: no data"), std::string::npos);
  EXPECT_NE(html.find("<tr class=\"best\"><td>2</td>"), std::string::npos);
  EXPECT_NE(html.find("/*plotly*/"), std::string::npos);
  // the diagnostic and the failure are errors; nothing else was found
  EXPECT_NE(html.find("2 errors, 0 warnings, 0 notes."), std::string::npos);
}

// The findings card lists every finding with its severity, its analysis and a link to it, and
// counts notes apart from warnings (a composite report once said "3 warnings" for 1 and 2 notes).
TEST(Report, FindingsAreListedWithLinksAndNotesAreNotWarnings) {
  Report r = sample();
  r.sections[0].diagnostics.push_back({"warning", "b is beyond 0.1 R1", ""});
  r.sections[0].diagnostics.push_back({"info", "the corner stress depends on N", ""});
  r.sections[0].diagnostics.push_back({"info", "a second note", ""});
  const std::string html = to_html(r, "");
  EXPECT_NE(html.find("2 errors, 1 warning, 2 notes."), std::string::npos);
  const std::size_t card = html.find("<ul class=\"findings\">");
  ASSERT_NE(card, std::string::npos);
  const std::string list = html.substr(card, html.find("</ul>", card) - card);
  EXPECT_NE(list.find("<li class=\"info\"><span class=\"sev\">note</span><a "
                      "href=\"#hinge-finding-3\">Hinge</a>: the corner stress depends on N</li>"),
            std::string::npos)
      << list;
  EXPECT_NE(list.find("<li class=\"warning\"><span class=\"sev\">warning</span><a "
                      "href=\"#hinge-finding-2\">Hinge</a>: b is beyond 0.1 R1</li>"),
            std::string::npos);
  EXPECT_NE(list.find("href=\"#contact\">Contact</a>: could not run: no data"), std::string::npos);
  // each link has its target
  EXPECT_NE(html.find("id=\"hinge-finding-3\""), std::string::npos);
  EXPECT_NE(html.find("<section id=\"contact\""), std::string::npos);
}

TEST(Report, NumberedGridsCountFromOneAndCarryTheirNote) {
  Report r = sample();
  r.sections[0].grids[0].numbered = true;
  r.sections[0].grids[0].note = "Best design, highlighted: #2 (R1 = 2 mm).";
  const std::string html = to_html(r, "");
  EXPECT_NE(html.find("<tr><th>#</th><th>R1 [mm]</th>"), std::string::npos);
  EXPECT_NE(html.find("<tr class=\"best\"><td class=\"n\">2</td><td>2</td>"), std::string::npos);
  EXPECT_NE(html.find("<p class=\"note\">Best design, highlighted: #2 (R1 = 2 mm).</p>"),
            std::string::npos);
  // a wide grid scrolls inside its card
  EXPECT_NE(html.find(".grid{overflow-x:auto"), std::string::npos);
}

TEST(Report, DrawingsHaveCaptionLegendAndScaleBar) {
  Report r = sample();
  r.sections[0].drawing_keys.push_back({"Catena hinge", {{"plate", 0x1f77b4u}}, 20.0});
  const std::string html = to_html(r, "");
  EXPECT_NE(html.find("<div class=\"caption\">Catena hinge</div>"), std::string::npos);
  EXPECT_NE(html.find("background:#1f77b4\"></span>plate"), std::string::npos);
  EXPECT_NE(html.find("scale bar 20 mm"), std::string::npos);
}

TEST(Report, IndexAxesAskForIntegerTicks) {
  Report r = sample();
  r.sections[0].charts[0].integer_x = true;
  EXPECT_NE(to_html(r, "").find("\"integer\":true"), std::string::npos);
  EXPECT_NE(to_html(sample(), "").find("\"integer\":false"), std::string::npos);
}

// Markers (labelled vertical lines) and frames (an animation) go to a second chart list with
// its own script; a report without them has neither, so that it stays as it was before them.
TEST(Report, MarkersAndFramesGoToTheSecondListOnlyWhenPresent) {
  const std::string plain = to_html(sample(), "");
  EXPECT_EQ(plain.find("catena-charts-extra"), std::string::npos);
  EXPECT_EQ(plain.find("\"markers\""), std::string::npos);

  Report r = sample();
  ReportChart spectrum;
  spectrum.title = "Spectrum";
  spectrum.traces.push_back({"upper", {0.0, 10.0}, {1.0, 2.0}});
  spectrum.markers.push_back({24.83, "mesh </script>"});
  ReportChart loop;
  loop.title = "Loop";
  loop.equal_axes = true;
  loop.traces.push_back({"wheel", {0.0, 1.0}, {0.0, 1.0}});
  loop.traces.push_back({"chain", {0.0}, {2.0}});
  loop.frames.push_back({"t = 0 s", {{"chain", {0.0}, {2.0}}}});
  loop.frames.push_back({"t = 1 s", {{"chain", {0.5}, {2.5}}}});
  r.sections[0].charts.push_back(spectrum);
  r.sections[0].charts.push_back(loop);
  r.sections[0].charts.push_back(sample().sections[0].charts[0]);  // a plain one after them
  const std::string html = to_html(r, "");
  // four chart elements, numbered in page order; the animation is taller (slider, buttons)
  EXPECT_NE(html.find("<div class=\"chart\" id=\"catena-chart-1\"></div>"), std::string::npos);
  EXPECT_NE(html.find("<div class=\"chart\" id=\"catena-chart-2\" style=\"height:600px\">"),
            std::string::npos);
  EXPECT_NE(html.find("<div class=\"chart\" id=\"catena-chart-3\"></div>"), std::string::npos);
  const std::size_t plain_list = html.find("id=\"catena-charts\">");
  const std::size_t extra_list = html.find("id=\"catena-charts-extra\">");
  ASSERT_NE(plain_list, std::string::npos);
  ASSERT_NE(extra_list, std::string::npos);
  const std::string first =
      html.substr(plain_list, html.find("</script>", plain_list) - plain_list);
  const std::string second =
      html.substr(extra_list, html.find("</script>", extra_list) - extra_list);
  EXPECT_NE(first.find("\"id\":\"catena-chart-0\""), std::string::npos);
  EXPECT_NE(first.find("},{\"id\":\"catena-chart-3\""), std::string::npos);  // one list, a comma
  EXPECT_EQ(first.find("catena-chart-1"), std::string::npos);
  EXPECT_NE(second.find("[{\"id\":\"catena-chart-1\""), std::string::npos);
  EXPECT_NE(second.find("\"markers\":[{\"x\":24.83,\"label\":\"mesh \\u003c/script\\u003e\"}]"),
            std::string::npos)
      << second;
  EXPECT_NE(second.find("},{\"id\":\"catena-chart-2\""), std::string::npos);
  EXPECT_NE(
      second.find("\"frames\":[{\"name\":\"t = 0 s\",\"traces\":[{\"name\":\"chain\",\"x\":[0],"
                  "\"y\":[2]}]},{\"name\":\"t = 1 s\""),
      std::string::npos)
      << second;
  // the second list's script: shapes and annotations for markers, a slider and buttons
  EXPECT_NE(html.find("layout.sliders"), std::string::npos);
  EXPECT_NE(html.find("Plotly.addFrames"), std::string::npos);
}

TEST(Report, InlinedDrawingsGetUniqueIds) {
  const std::string html = to_html(sample(), "");
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_NE(html.find("id=\"catena-d0-glyph0\""), std::string::npos);
  EXPECT_NE(html.find("xlink:href=\"#catena-d0-glyph0\""), std::string::npos);
  EXPECT_NE(html.find("url(#catena-d0-clip1)"), std::string::npos);
  EXPECT_NE(html.find("id=\"catena-d1-glyph0\""), std::string::npos);
  EXPECT_EQ(html.find("id=\"glyph0\""), std::string::npos);
}

// The case's prose: its description opens the report, a table's note heads its section; a blank
// line starts a paragraph, other line breaks are spaces, and the text is escaped.
TEST(Report, DescriptionAndNotesArePlainParagraphs) {
  Report r = sample();
  r.description = "The thesis as printed\nand Catena's design.\n\n  <b>Why</b> it fails. \n";
  r.sections[0].note = "R1 = 34 mm > R1max";
  const std::string html = to_html(r, "");
  EXPECT_NE(html.find("<section id=\"about\"><p>The thesis as printed and Catena&#39;s design.</p>"
                      "<p>&lt;b&gt;Why&lt;/b&gt; it fails.</p></section>"),
            std::string::npos);
  EXPECT_LT(html.find("id=\"about\""), html.find("id=\"summary\""));  // before the findings
  const std::size_t hinge = html.find("<section id=\"hinge\" class=\"analysis\">");
  const std::size_t note = html.find("<div class=\"note\"><p>R1 = 34 mm &gt; R1max</p></div>");
  ASSERT_NE(note, std::string::npos);
  EXPECT_LT(hinge, note);
  EXPECT_LT(note, html.find("class=\"diagnostic error\"", hinge));  // above the findings
  // none given: no empty box
  EXPECT_EQ(to_html(sample(), "").find("id=\"about\""), std::string::npos);
  EXPECT_EQ(to_html(sample(), "").find("class=\"note\""), std::string::npos);
}

TEST(Report, HtmlEscape) {
  EXPECT_EQ(html_escape("<a href='x'>&\""), "&lt;a href=&#39;x&#39;&gt;&amp;&quot;");
}

}  // namespace
}  // namespace catena::io
