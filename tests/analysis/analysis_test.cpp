// The analysis interface: the registry's tables are well formed, binding text gives SI values and
// every problem at once, a run by name equals the model called directly, and the JSON writer
// keeps the contract's number forms.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "catena/catena.hpp"
#include "catena/io/bind.hpp"
#include "catena/io/record.hpp"
#include "catena/pocketwheel/run_on.hpp"

namespace {

using catena::analysis::Parameter;
using catena::analysis::ParameterType;
using catena::analysis::Value;

constexpr double kLengthTol = 1e-15;  // [m] parsing "64 mm" is one multiplication

TEST(Registry, EveryParameterTableIsWellFormed) {
  ASSERT_FALSE(catena::analyses().empty());
  std::set<std::string> names;
  for (const catena::analysis::Analysis* a : catena::analyses()) {
    EXPECT_TRUE(names.insert(a->name).second) << "duplicate analysis " << a->name;
    EXPECT_FALSE(a->title.empty()) << a->name;
    EXPECT_FALSE(a->docs.empty()) << a->name;
    EXPECT_FALSE(a->command.empty()) << a->name;
    EXPECT_EQ(catena::find_analysis(a->name), a);
    std::set<std::string> keys;
    for (const Parameter& p : a->parameters) {
      EXPECT_TRUE(keys.insert(p.name).second) << a->name << ": duplicate " << p.name;
      EXPECT_FALSE(p.doc.empty()) << a->name << "." << p.name;
      for (char c : p.name) {
        EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_')
            << a->name << "." << p.name << ": a key is a word (flag --" << p.name << ")";
      }
      if (p.type == ParameterType::kChoice) {
        EXPECT_FALSE(p.choices.empty()) << a->name << "." << p.name;
      }
      EXPECT_FALSE(p.required && !p.default_text.empty())
          << a->name << "." << p.name << ": required parameters have no default";
    }
  }
}

// Each default is what a user would type: it binds without a problem, for every analysis.
TEST(Registry, EveryDefaultBindsWithoutAProblem) {
  for (const catena::analysis::Analysis* a : catena::analyses()) {
    std::vector<catena::Issue> issues;
    const catena::analysis::Inputs in = catena::io::bind(*a, {}, issues);
    for (const catena::Issue& issue : issues) {
      EXPECT_EQ(issue.value, "(missing)")
          << a->name << ": only missing required values may be reported, got "
          << catena::to_string(issue);
    }
    for (const Parameter& p : a->parameters) {
      if (p.default_text.empty() || p.type == ParameterType::kFlag) continue;
      EXPECT_TRUE(in.present(p.name)) << a->name << "." << p.name;
      if (p.type == ParameterType::kQuantity || p.type == ParameterType::kNumber) {
        EXPECT_TRUE(std::isfinite(in.number(p.name))) << a->name << "." << p.name;
      }
    }
  }
}

TEST(Registry, RunByNameEqualsTheModelCalledDirectly) {
  const catena::analysis::Record r = catena::run("pocketwheel", {{"pitch", "64 mm"},
                                                                 {"wire", "18"},
                                                                 {"teeth", "8"},
                                                                 {"omega", "47.75 rpm"},
                                                                 {"guide", "tangential"},
                                                                 {"points", "31"}});
  namespace pw = catena::pocketwheel;
  const pw::RunOnResult direct =
      pw::run_on({.pitch = 0.064, .wire = 0.018, .teeth = 8},
                 {.kind = pw::GuideKind::kTangential, .end_distance = 0.256},
                 {.omega = 47.75 * 2.0 * M_PI / 60.0, .points = 31});
  EXPECT_NEAR(r.data.at("pitch").as_number(), 0.064, kLengthTol);
  EXPECT_EQ(r.data.at("pitch_radius").as_number(), direct.plan.geometry.pitch_radius);
  EXPECT_EQ(r.data.at("extremes").at("ax_max").as_number(), direct.extremes.ax_max);
  EXPECT_EQ(r.data.at("series").at("x").numbers(), direct.series.x);
  EXPECT_EQ(r.data.at("teeth").as_integer(), 8);
  EXPECT_EQ(r.columns.size(), 5u) << "phi, time, x, vx, ax";
  EXPECT_EQ(r.drawings.size(), 1u);
  EXPECT_FALSE(r.table.empty());
}

TEST(Registry, EveryProblemAtOnceNamedByKey) {
  try {
    catena::run("pocketwheel",
                {{"wire", "18 kg"}, {"teeth", "2"}, {"omega", "5 Hz"}, {"guide", "sideways"}});
    FAIL() << "expected InputError";
  } catch (const catena::InputError& e) {
    std::set<std::string> fields;
    for (const catena::Issue& issue : e.issues()) fields.insert(issue.field);
    EXPECT_EQ(fields, (std::set<std::string>{"pitch", "wire", "teeth", "omega", "guide"}))
        << e.what();
  }
  EXPECT_THROW(catena::run("no_such_analysis", {}), catena::InputError);
}

TEST(Registry, TheExampleFillsWhatIsMissing) {
  const catena::analysis::Record r = catena::run("pocketwheel", {{"example", "true"}});
  ASSERT_TRUE(r.data.is_array());
  EXPECT_EQ(r.data.size(), 3u) << "free, chordal, tangential";
  EXPECT_TRUE(r.drawings.empty());
  EXPECT_FALSE(r.drawing_unavailable.empty());
}

TEST(Bind, CaseFileTypesAreChecked) {
  const catena::analysis::Analysis& a = *catena::find_analysis("pocketwheel");
  using T = catena::io::RawInput::Type;
  std::vector<catena::Issue> issues;
  catena::io::bind(a,
                   {{"pitch", "true", T::kBoolean, {}, {}},
                    {"wire", "18", T::kNumber, {}, {}},
                    {"example", "18", T::kNumber, {}, {}},
                    {"guide", "sideways", T::kText, {}, {}},
                    {"colour", "red", T::kText, {}, {}}},
                   issues);
  std::set<std::string> fields;
  for (const catena::Issue& issue : issues) fields.insert(issue.field);
  EXPECT_EQ(fields,
            (std::set<std::string>{"pitch", "example", "guide", "colour", "teeth", "omega"}));
}

TEST(ValueJson, IntegersRealsNullsAndOrderAsTheContractPrints) {
  Value v = Value::object();
  v["teeth"] = 8;
  v["pitch"] = 8.0;
  v["nan"] = std::nan("");
  v["list"] = std::vector<double>{0.1, 1e-300};
  v["none"] = std::optional<double>();
  v["a"] = Value::object({{"z", 1}, {"b", true}});
  EXPECT_EQ(catena::io::to_json(v, -1),
            R"({"teeth":8,"pitch":8.0,"nan":null,"list":[0.1,1e-300],"none":null,)"
            R"("a":{"z":1,"b":true}})");
  EXPECT_TRUE(v.has_non_finite());
  const Value back = catena::io::parse_json(catena::io::to_json(v));
  EXPECT_EQ(catena::io::to_json(back), catena::io::to_json(v));
}

TEST(Csv, HeaderThenRowsWithTwelveDigits) {
  EXPECT_EQ(catena::io::to_csv({{"a", {1.0, 1.0 / 3.0}}, {"b", {2.0, -0.5}}}),
            "a,b\n1,2\n0.333333333333,-0.5\n");
}

}  // namespace

namespace {

// A result that is not finite is an error diagnostic naming the field; an absent value (null)
// is not; units and the diagnostics array are not results.
TEST(NonFinite, FieldsAreFoundByPathAndCountedPerArray) {
  const double inf = INFINITY;
  Value data = Value::object({{"a", 1.0},
                              {"b", Value::object({{"c", -inf}, {"absent", Value()}})},
                              {"series", std::vector<double>{1.0, NAN, inf, 2.0}},
                              {"runs", Value(Value::Array{Value::object({{"x", NAN}})})},
                              {"units", Value::object({{"a", "m"}})},
                              {"diagnostics", Value::array()}});
  const std::vector<catena::analysis::NonFinite> f = catena::analysis::non_finite_fields(data);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].path, "b.c");
  EXPECT_EQ(f[0].count, 1u);
  EXPECT_EQ(f[1].path, "series");
  EXPECT_EQ(f[1].count, 2u);
  EXPECT_EQ(f[1].total, 4u);
  EXPECT_TRUE(std::isnan(f[1].first));
  EXPECT_EQ(f[2].path, "runs[0].x");

  catena::analysis::Record record;
  record.data = data;
  catena::analysis::diagnose_non_finite(record);
  ASSERT_EQ(record.diagnostics.size(), 3u);
  for (const catena::Diagnostic& d : record.diagnostics) {
    EXPECT_EQ(d.severity, catena::Diagnostic::Severity::kError);
    EXPECT_EQ(d.code, "result.non_finite");
    EXPECT_TRUE(std::isfinite(d.value));
  }
  EXPECT_NE(record.diagnostics[1].message.find("'series'"), std::string::npos);
  EXPECT_NE(record.diagnostics[1].message.find("2 of 4"), std::string::npos);
  EXPECT_EQ(record.data.at("diagnostics").size(), 3u);  // in the JSON's own array too
  EXPECT_EQ(record.data.at("diagnostics").as_array()[0].at("severity").as_string(), "error");
}

TEST(NonFinite, EvaluateDiagnosesWhatAnAnalysisLeavesNonFinite) {
  // The inputs that overflowed a model (issue 18: pocketwheel --omega 1e200 and three more) are
  // refused at the boundary now, so an analysis that returns ±inf stands in for the next one:
  // evaluate, the one path of every front end, must turn it into the error diagnostic.
  catena::analysis::Analysis a;
  a.name = "overflowing";
  catena::analysis::set_functions<double>(
      a, [](const catena::analysis::Inputs&) { return INFINITY; },
      [](const double& x, const catena::analysis::Inputs&) {
        catena::analysis::Record r;
        r.data = Value::object({{"x", x}, {"diagnostics", Value::array()}});
        return r;
      });
  const catena::analysis::Record r = a.evaluate(catena::analysis::Inputs(&a.parameters));
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "result.non_finite");
  EXPECT_NE(r.diagnostics[0].message.find("'x'"), std::string::npos) << r.diagnostics[0].message;
  // a registered analysis at the edge of its ranges (10 000 rad/s) has none
  const catena::analysis::Record ok = catena::run(
      "pocketwheel", {{"pitch", "64 mm"}, {"wire", "18"}, {"teeth", "8"}, {"omega", "10000"}});
  EXPECT_TRUE(catena::analysis::non_finite_fields(ok.data).empty());
  for (const catena::Diagnostic& d : ok.diagnostics) EXPECT_NE(d.code, "result.non_finite");
}

// A multiple in a message's words, from its constant (the guard on energy from nothing's "more
// than twice the" from kEnergyGainBound = 2, docs/models/dynamics.md): the word at exactly 2,
// the number otherwise, with the digits it needs to read back as itself (never rounded to a
// number it is not).
TEST(TimesText, NamesTheMultipleInWords) {
  EXPECT_EQ(catena::analysis::times_text(2.0), "twice");
  EXPECT_EQ(catena::analysis::times_text(2.0000001), "2.0000001 times");
  EXPECT_EQ(catena::analysis::times_text(1.0000001), "1.0000001 times");
  EXPECT_EQ(catena::analysis::times_text(3.0), "3 times");
  EXPECT_EQ(catena::analysis::times_text(1.5), "1.5 times");
}

}  // namespace
