#include "catena/io/record.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace catena::io {
namespace {

using analysis::Record;
using analysis::Value;

const ReportRow* row_named(const ReportSection& s, const std::string& name) {
  for (const ReportRow& r : s.tables.at(0).rows)
    if (r.name == name) return &r;
  return nullptr;
}

// A result with nested layouts, as the strength analysis has them.
Record layouts_record() {
  Record rec;
  Value forces = Value::object({{"lower_outer", 12345.0}, {"upper_outer", -0.0}});
  Value layout = Value::object({{"plate_force", forces}, {"moment_at", 0.012}});
  rec.data = Value::object({{"source", "test"},
                            {"layouts", Value::object({{"layout_1", layout}})},
                            {"tilt", -1e-9},
                            {"units", analysis::units_value({{"plate_force", "N"},
                                                             {"lower_outer", "N"},
                                                             {"upper_outer", "N"},
                                                             {"moment_at", "m"},
                                                             {"tilt", "rad"}})}});
  return rec;
}

TEST(ReportSection, FieldsWithoutLabelsAreNamedByTheirPath) {
  const ReportSection s = report_section(layouts_record(), "x", "X", "");
  const ReportRow* r = row_named(s, "layouts.layout_1.plate_force.lower_outer");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->value, "12345");
  EXPECT_EQ(r->unit, "N");
}

TEST(ReportSection, LabelsNameFieldsWithTheirSymbolsAndUnits) {
  Record rec = layouts_record();
  rec.labels = {{"layouts", "", ""},
                {"layout_1", "Layout 1", ""},
                {"plate_force.lower_outer", "Plate force, lower outer F21", "kN"},
                {"lower_outer", "never: a shorter match", ""},
                {"plate_force.upper_outer", "Plate force, upper outer F22", "kN"}};
  const ReportSection s = report_section(rec, "x", "X", "");
  const ReportRow* r = row_named(s, "Layout 1 › Plate force, lower outer F21");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->value, "12.345");
  EXPECT_EQ(r->unit, "kN");
  // never "-0": a negative zero and a negative value that rounds to nothing
  const ReportRow* zero = row_named(s, "Layout 1 › Plate force, upper outer F22");
  ASSERT_NE(zero, nullptr);
  EXPECT_EQ(zero->value, "0");
  // an unlabelled field keeps its path and display unit
  const ReportRow* at = row_named(s, "layouts.layout_1.moment_at");
  ASSERT_NE(at, nullptr);
  EXPECT_EQ(at->value, "12");
  EXPECT_EQ(at->unit, "mm");
}

TEST(ReportSection, NegativeZeroIsWrittenAsZero) {
  EXPECT_EQ(format_cell(Value(-0.0)), "0");
  EXPECT_EQ(format_cell(Value(-1e-30), 1.0), "-1e-30");  // small, not zero: kept
  EXPECT_EQ(format_cell(Value(-2.5)), "-2.5");
}

TEST(ReportSection, LimitsAreInTheDisplayUnitsOfTheTables) {
  Record rec = layouts_record();
  rec.diagnostics.push_back(
      {Diagnostic::Severity::kWarning, "t.width", "b > 0.1 R1", 0.0039, 0.0034, "m"});
  rec.diagnostics.push_back(
      {Diagnostic::Severity::kInfeasible, "t.stress", "σ > [σ]", 1.851e9, 1.6e9, "Pa"});
  rec.diagnostics.push_back(
      {Diagnostic::Severity::kWarning, "t.turn", "γ > γmax", 1.0066, std::numbers::pi / 4, "rad"});
  rec.diagnostics.push_back({Diagnostic::Severity::kWarning, "t.ratio", "n < 1", 0.9, 1.0, ""});
  rec.diagnostics.push_back({Diagnostic::Severity::kInfo, "t.note", "a note", 5.0, 0.0, "Pa"});
  const ReportSection s = report_section(rec, "x", "X", "");
  ASSERT_EQ(s.diagnostics.size(), 5u);
  EXPECT_EQ(s.diagnostics[0].limit, "value 3.9 mm, limit 3.4 mm");
  EXPECT_EQ(s.diagnostics[1].limit, "value 1851 MPa, limit 1600 MPa");
  EXPECT_EQ(s.diagnostics[1].severity, "error");
  EXPECT_EQ(s.diagnostics[2].limit, "value 57.6739°, limit 45°");
  EXPECT_EQ(s.diagnostics[3].limit, "value 0.9, limit 1");
  EXPECT_EQ(s.diagnostics[4].limit, "");  // a note's numbers are context, not a check
  EXPECT_EQ(s.diagnostics[4].severity, "info");
  for (const ReportDiagnostic& d : s.diagnostics)
    EXPECT_EQ(d.limit.find("SI"), std::string::npos) << d.limit;
}

TEST(ReportSection, SweepRowsAreNumberedAndTheBestIsNamedByItsInputs) {
  Record rec;
  Value rows = Value::array();
  for (double r1 : {0.010, 0.015, 0.020})
    rows.push_back(Value::object({{"R1", r1}, {"R2", 3 * r1}, {"feasible", r1 < 0.02}}));
  rec.data = Value::object({{"source", "test"},
                            {"rows", rows},
                            {"best", Value(1LL)},
                            {"criterion", "the lowest stress"},
                            {"units", analysis::units_value({{"R1", "m"}, {"R2", "m"}})}});
  rec.design_keys = {"R1", "R2"};
  const ReportSection s = report_section(rec, "x", "X", "");
  ASSERT_EQ(s.grids.size(), 1u);
  const ReportGrid& g = s.grids[0];
  EXPECT_TRUE(g.numbered);
  EXPECT_EQ(g.columns, (std::vector<std::string>{"R1 [mm]", "R2 [mm]", "feasible"}));
  EXPECT_EQ(g.highlighted, (std::vector<bool>{false, true, false}));
  EXPECT_EQ(g.note, "Best design, highlighted: #2 (R1 = 15 mm, R2 = 45 mm); the lowest stress.");
  const ReportRow* best = row_named(s, "best design");
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->value, "#2 (R1 = 15 mm, R2 = 45 mm)");
  EXPECT_EQ(row_named(s, "best"), nullptr);  // no 0-based index left in the results
}

TEST(ReportSection, DrawingsGetACaptionALegendAndAScaleBar) {
  Record rec = layouts_record();
  Drawing d;
  d.title = "Catena hinge";
  d.polylines.push_back({"plate", {{0.0, 0.0}, {0.1, 0.0}, {0.1, 0.05}}, true, 0.35, 0x1f77b4});
  d.polylines.push_back({"roller", {{0.02, 0.01}, {0.03, 0.02}}, false, 0.35, 0xd62728});
  d.polylines.push_back({"plate", {{0.0, 0.01}, {0.01, 0.01}}, false, 0.35, 0x1f77b4});
  rec.drawings.push_back(d);
  const ReportSection s = report_section(rec, "x", "X", "");
  ASSERT_EQ(s.drawing_keys.size(), 1u);
  const ReportDrawingKey& k = s.drawing_keys[0];
  EXPECT_EQ(k.caption, "Catena hinge");
  ASSERT_EQ(k.legend.size(), 2u);  // each layer once
  EXPECT_EQ(k.legend[0], (std::pair<std::string, unsigned>{"plate", 0x1f77b4u}));
  EXPECT_EQ(k.legend[1], (std::pair<std::string, unsigned>{"roller", 0xd62728u}));
  EXPECT_DOUBLE_EQ(k.scale_bar_mm, 20.0);  // a round length near a fifth of 100 mm
  // the bar is drawn: the SVG has one more path than the drawing has polylines
  std::size_t paths = 0;
  for (std::size_t at = s.drawings_svg[0].find("<path"); at != std::string::npos;
       at = s.drawings_svg[0].find("<path", at + 1))
    ++paths;
  EXPECT_EQ(paths, d.polylines.size() + 1);
}

}  // namespace
}  // namespace catena::io
