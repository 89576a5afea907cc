// `catena run` and `catena report`: case files as an engineer writes them, and every kind of
// mistake in them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "../read_text.hpp"
#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kExamples = CATENA_EXAMPLES_DIR;

std::string write_case(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("catena_case_" + name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

nlohmann::json run_json(const std::string& args) {
  const CliRun r = run(args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

TEST(CaseCli, EachExampleGivesWhatItsSubcommandGives) {
  // The case runner must feed the very flags a user would type: the results are identical.
  const auto hinge = run_json("run " + kExamples + "/000_thesis_rolling_hinge.toml");
  const auto direct_hinge = run_json(
      "hinge --pitch 125mm --pin-diameter 40mm --half-thickness 8mm --contact-length 24mm "
      "--teeth 8 --strokes 2 --tension 29.4kN --modulus 210GPa --poisson 0.3 "
      "--allowable-shear 120MPa --allowable-contact 1600MPa --friction 0.15 --plate-radius 34mm "
      "--roller-radius 35.4mm --format json");
  ASSERT_TRUE(hinge["analyses"].contains("hinge"));
  for (const char* key : {"R2", "contact_stress", "rolling_limit", "face_margin", "pitch_change"})
    EXPECT_EQ(hinge["analyses"]["hinge"][key], direct_hinge[key]) << key;
  ASSERT_TRUE(hinge["analyses"].contains("hinge_sweep"));
  EXPECT_EQ(hinge["analyses"]["hinge_sweep"]["rows"].size(), 24u);
  // engagement: chain.type = rolling-hinge implies --hinge rolling; the shared sliding friction
  // of [material] is not passed to a rolling hinge
  const auto direct_engagement = run_json(
      "engagement --hinge rolling --pitch 125mm --pin-diameter 40mm --half-thickness 8mm "
      "--teeth 8 --strokes 2 --tension 29.4kN --plate-radius 15mm --flank-angle 21.62deg "
      "--format json");
  EXPECT_EQ(hinge["analyses"]["engagement"], direct_engagement);
  const auto direct_warp = run_json(
      "warp --hinge rolling --pin-diameter 40mm --modulus 210GPa --poisson 0.3 "
      "--heights '0, 8 mm, 48 mm, 56 mm' --widths 8mm --stiffness 2e8 "
      "--force '30 kN, 35 kN, 40 kN' --load-height '28 mm, 28.5 mm, 29 mm, 29.5 mm, 30 mm' "
      "--plate-radius 34mm --roller-radius 35.4mm --format json");
  EXPECT_EQ(hinge["analyses"]["warp"], direct_warp);
  const auto direct_strength = run_json(
      "strength --hinge rolling --pin-diameter 40mm --modulus 210GPa --poisson 0.3 "
      "--tension 29.4kN --allowable-contact 1600MPa --heights '0, 8 mm, 48 mm, 56 mm' "
      "--widths 8mm --plate-width 80mm --end-distance 40mm --plate-radius 34mm "
      "--roller-radius 35.4mm --roller-yield 600MPa --plate-yield 355MPa --plate-ultimate 490MPa "
      "--safety-factor 1.5 --format json");
  EXPECT_EQ(hinge["analyses"]["strength"], direct_strength);

  const auto contact = run_json("run " + kExamples + "/001_roller_chain_skew.toml");
  const auto direct_contact = run_json(
      "contact --chain 12B --load 1kN --tooth-radius 15.56mm --profile concave "
      "--skew-gauge-dh 0.155mm --skew-gauge-base 12.7mm --format json");
  EXPECT_EQ(contact["analyses"]["contact"], direct_contact);

  // the paper's comparison: one analysis table per run-on ("pocketwheel-<label>")
  const auto wheel = run_json("run " + kExamples + "/003_pocket_wheel.toml");
  for (const std::string guide : {"free", "chordal", "tangential"}) {
    const auto direct_wheel = run_json(
        "pocketwheel --pitch 64mm --wire 18mm --teeth 8 --omega 5 --guide " +
        std::string(guide == "free" ? "none" : guide) + " --guide-end 256mm --format json");
    EXPECT_EQ(wheel["analyses"]["pocketwheel-" + guide], direct_wheel) << guide;
  }
  EXPECT_EQ(wheel["case_sha256"].get<std::string>().size(), 64u);

  // seed 002: the composite link, bilateral and unilateral (a boolean key becomes a bare flag)
  const auto ring = run_json("run " + kExamples + "/002_composite_link.toml");
  const std::string ring_flags =
      "ring --inner-radius 4.72mm --outer-radius 10mm --thickness 1mm --E-r 10GPa --E-phi 40GPa "
      "--G 4GPa --nu-phi-r 0.28 --gap 0.02mm --format json";
  EXPECT_EQ(ring["analyses"]["ring"], run_json(ring_flags));
  EXPECT_EQ(ring["analyses"]["ring-unilateral"], run_json(ring_flags + " --unilateral"));

  // the conveyor loop: `catena loop` reads the [loop] table of the very case file
  const auto loop = run_json("run " + kExamples + "/000_loop.toml");
  const auto direct_loop = run_json("loop " + kExamples + "/000_loop.toml --format json");
  EXPECT_EQ(loop["analyses"]["loop"], direct_loop);

  // the chain-loop dynamics: `catena dynamics` reads the [dynamics] table of the very case file;
  // equal but for the wall time and the real-time factor it implies (measured, never the same)
  auto dynamics = run_json("run " + kExamples + "/dynamics_12B.toml")["analyses"]["dynamics"];
  auto direct_dynamics = run_json("dynamics " + kExamples + "/dynamics_12B.toml --format json");
  ASSERT_TRUE(dynamics.contains("summary"));
  ASSERT_TRUE(direct_dynamics.contains("summary"));
  for (auto* j : {&dynamics, &direct_dynamics}) {
    EXPECT_GT((*j)["summary"]["wall_time"].get<double>(), 0.0);
    (*j)["summary"].erase("wall_time");
    (*j)["summary"].erase("real_time_factor");
  }
  EXPECT_EQ(dynamics, direct_dynamics);
}

// Issue 19: the built-in case runs the thesis' design as printed and Catena's design for the same
// chain ("-catena" tables). Catena's design must carry no error: every analysis passes, and the
// only warnings left are the rolling hinge type's own (friction holds the rolling through a few
// degrees only, eq. 21; the aperture guides the rest, the wear run counts it as sliding). The
// printed design keeps its errors, the findings the description explains. Same sprocket, flank,
// force and allowables on both sides: Catena's design does not pass by asking for less.
TEST(CaseCli, BuiltInCaseShowsCatenasDesignPassingBesideThePrintedOne) {
  const auto tree = run_json("report --format json");
  ASSERT_TRUE(tree.contains("analyses"));
  const auto& a = tree["analyses"];
  const auto codes = [&](const std::string& name, const std::string& severity) {
    std::set<std::string> out;
    // a sweep has no diagnostics of its own (its rows say feasible or not)
    for (const auto& d : a[name].value("diagnostics", nlohmann::json::array()))
      if (d["severity"] == severity) out.insert(d["code"].get<std::string>());
    return out;
  };
  const std::set<std::string> accepted = {"hinge.rolling_limit_below_working_turn",
                                          "wear.slides_beyond_rolling_limit"};
  int catena_runs = 0;
  for (const char* base : {"hinge", "hinge_sweep", "engagement", "warp", "strength", "wear"}) {
    const std::string name = std::string(base) + "-catena";
    ASSERT_TRUE(a.contains(name)) << name;
    ASSERT_TRUE(a.contains(base)) << base;  // the printed design's run stays beside it
    ++catena_runs;
    EXPECT_TRUE(codes(name, "error").empty()) << name;
    EXPECT_TRUE(codes(name, "infeasible").empty()) << name;
    for (const std::string& w : codes(name, "warning"))
      EXPECT_TRUE(accepted.count(w)) << name << ": " << w;
  }
  EXPECT_EQ(catena_runs, 6);
  // the printed design's findings stay: its contact leaves the face and the plate's arc
  EXPECT_TRUE(codes("hinge", "infeasible").count("hinge.contact_leaves_face"));
  EXPECT_TRUE(codes("engagement", "infeasible").count("engagement.contact_off_arc"));
  // the same chain, sprocket, flank and force on both sides
  EXPECT_EQ(a["engagement-catena"]["angles"], a["engagement"]["angles"]);
  EXPECT_EQ(a["engagement-catena"]["tension"], a["engagement"]["tension"]);
  EXPECT_EQ(a["engagement-catena"]["pitch"], a["engagement"]["pitch"]);
  // the same allowables: every strength check of Catena's design against the printed one's
  const auto& checks = a["strength-catena"]["checks"];
  ASSERT_EQ(checks.size(), a["strength"]["checks"].size());
  for (std::size_t i = 0; i < checks.size(); ++i) {
    EXPECT_EQ(checks[i]["name"], a["strength"]["checks"][i]["name"]);
    EXPECT_EQ(checks[i]["allowable"], a["strength"]["checks"][i]["allowable"]);
    EXPECT_EQ(checks[i]["required"], a["strength"]["checks"][i]["required"]);
    EXPECT_TRUE(checks[i]["ok"].get<bool>()) << checks[i]["name"];
  }
  // the sweep on Catena's pin: the rows either side of the chosen R1 = 12 mm are feasible
  const auto& rows = a["hinge_sweep-catena"]["rows"];
  int around = 0;
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    if (rows[i]["R1"].get<double>() <= 0.012 && rows[i + 1]["R1"].get<double>() >= 0.012) {
      EXPECT_TRUE(rows[i]["feasible"].get<bool>());
      EXPECT_TRUE(rows[i + 1]["feasible"].get<bool>());
      ++around;
    }
  }
  EXPECT_EQ(around, 1);
  // the Hertz stress of the hinge analysis is within [σH] = 1.6 GPa, the contact on the face
  EXPECT_LE(a["hinge-catena"]["contact_stress"].get<double>(), 1600e6);
  EXPECT_GT(a["hinge-catena"]["face_margin"].get<double>(), 0.0);
  // the faces were made for a larger turn than the engagement asks of them (eq. 6 solved for γ)
  const auto& s = a["engagement-catena"]["series"];
  double turn = 0.0;
  for (std::size_t i = 0; i < s["xi"].size(); ++i) {
    const double xi = s["xi"][i], g = s["gamma"][i];
    turn = std::max({turn, std::abs(xi), std::abs(g - xi)});
  }
  const double r1 = a["hinge-catena"]["R1"], r2 = 0.0523;  // R2 given to engagement-catena
  EXPECT_LT(turn, a["hinge-catena"]["psi1_max"].get<double>() * (1.0 - r1 / r2));
  EXPECT_GT(turn, a["engagement-catena"]["gamma_sigma"].get<double>() / 2.0);  // uneven split
}

TEST(CaseCli, ReportIsOneSelfContainedHtmlFile) {
  const fs::path dir = fs::temp_directory_path() / "catena_report_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // the built-in case, from a directory with nothing in it
  const CliRun r = run("report -o " + (dir / "r.html").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string html = read_text(dir / "r.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  for (const char* fragment :
       {"<section id=\"hinge\" class=\"analysis\">",
        "<section id=\"hinge_sweep\" class=\"analysis\">",
        "<section id=\"wear\" class=\"analysis\">",
        "Elongation of the sliding- and the rolling-hinge chain", "class=\"diagnostic",
        "<div class=\"drawing\"><svg", "Plotly.newPlot", "SHA-256"})
    EXPECT_NE(html.find(fragment), std::string::npos) << fragment;
  // nothing loaded from elsewhere (the browser test also watches the network)
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link "), std::string::npos);
  // the hash in the report is the hash of the built-in case's bytes
  const std::string digest = run_json("report --format json")["case_sha256"];
  EXPECT_NE(html.find(digest), std::string::npos);
  const CliRun json = run("report " + kExamples + "/003_pocket_wheel.toml --format json");
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_TRUE(nlohmann::json::parse(json.out)["analyses"].contains("pocketwheel-chordal"));
  fs::remove_all(dir);
}

struct BadCase {
  const char* name;
  const char* text;
  std::vector<const char*> fragments;  // each must appear in stderr
};

class BadCaseFile : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadCaseFile, IsRefusedWithEveryProblemNamedAndNoReport) {
  const BadCase& c = GetParam();
  const std::string path = write_case(c.name, c.text);
  const fs::path out = fs::temp_directory_path() / (std::string("catena_bad_") + c.name + ".html");
  fs::remove(out);
  const CliRun r = run("report " + path + " -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_FALSE(fs::exists(out));
  for (const char* f : c.fragments)
    EXPECT_NE(r.err.find(f), std::string::npos) << f << "\n" << r.err;
  fs::remove(path);
}

const char* kHinge =
    "[chain]\ntype = \"rolling-hinge\"\npin_diameter = \"40 mm\"\nhalf_thickness = \"8 mm\"\n"
    "[sprocket]\nteeth = 8\n";

INSTANTIATE_TEST_SUITE_P(
    Kinds, BadCaseFile,
    ::testing::Values(
        BadCase{"syntax", "[chain]\ntype = \"rolling-hinge\npitch = 3\n", {":2:", "valid TOML"}},
        BadCase{"top_key",
                "titel = \"x\"\n[chain]\ntype = \"round-link\"\n[analyses.pocketwheel]\n",
                {"titel", "did you mean 'title'"}},
        BadCase{"analysis_key",
                "[chain]\ntype = \"rolling-hinge\"\n[analyses.hinge]\nplate_radus = \"20 mm\"\n",
                {"analyses.hinge.plate_radus", "did you mean 'plate_radius'"}},
        BadCase{"analysis_name",
                "[chain]\ntype = \"rolling-hinge\"\n[analyses.hinje]\n",
                {"analyses.hinje", "did you mean 'hinge'"}},
        // a shared table's name as a top-level value (found by the fuzzer: it crashed)
        BadCase{"shared_table_as_value",
                "chain = \"12B\"\n[analyses.pocketwheel-tangential]\nguide = \"tangential\"\n",
                {"chain = 12B", "a [chain] table, not a value"}},
        BadCase{"shared_key",
                "[chain]\ntype = \"round-link\"\npich = \"64 mm\"\n[analyses.pocketwheel]\n",
                {"chain.pich", "did you mean 'pitch'"}},
        BadCase{"missing_type",
                "[chain]\npitch = \"64 mm\"\n[analyses.pocketwheel]\n",
                {"chain.type = (missing)"}},
        BadCase{"bad_type",
                "[chain]\ntype = \"round-lnk\"\n[analyses.pocketwheel]\n",
                {"chain.type", "did you mean 'round-link'"}},
        BadCase{"wrong_chain",
                "[chain]\ntype = \"round-link\"\n[analyses.hinge]\n",
                {"analyses.hinge", "applies to rolling-hinge"}},
        BadCase{"no_analyses", "[chain]\ntype = \"round-link\"\n", {"analyses = (missing)"}},
        BadCase{"output_key",
                "[chain]\ntype = \"rolling-hinge\"\n[analyses.hinge]\nformat = \"csv\"\n",
                {"analyses.hinge.format", "no output option"}},
        BadCase{"flag_type",
                "[chain]\ntype = \"rolling-hinge\"\n[analyses.hinge]\nflat = \"yes\"\n",
                {"analyses.hinge.flat", "true or false"}},
        BadCase{"bool_value",
                "[chain]\ntype = \"rolling-hinge\"\n[analyses.hinge]\nplate_radius = true\n",
                {"analyses.hinge.plate_radius", "bare number: mm"}},
        // model-level errors keep the case-file path, all at once, across analyses
        BadCase{"units_and_missing",
                "[chain]\ntype = \"rolling-hinge\"\npin_diameter = \"40 kg\"\n"
                "half_thickness = \"8 mm\"\n[sprocket]\nteeth = 8\n[analyses.hinge]\n"
                "[analyses.hinge_sweep]\ncount = 1\n",
                {"chain.pin_diameter = '40 kg'", "wrong dimension",
                 "analyses.hinge.plate_radius = (missing)", "analyses.hinge_sweep.count"}},
        // chain.type decides the engagement's hinge: the case file cannot contradict it
        BadCase{"implied_flag",
                "[chain]\ntype = \"sliding-hinge\"\n[analyses.engagement]\nhinge = \"rolling\"\n",
                {"analyses.engagement.hinge", "an option of 'engagement'"}},
        BadCase{"note_not_text",
                "[chain]\ntype = \"rolling-hinge\"\n[analyses.hinge]\nnote = 3\n",
                {"analyses.hinge.note", "a text: what this run shows"}},
        BadCase{"duplicate_shared",
                "[chain]\ntype = \"round-link\"\nteeth = 8\n[sprocket]\nteeth = 9\n"
                "[analyses.pocketwheel]\n",
                {"sprocket.teeth", "also given as chain.teeth"}}),
    [](const ::testing::TestParamInfo<BadCase>& param) { return std::string(param.param.name); });

// A case's description and a table's note are for the report's reader: shown there, left out
// of the inputs table, and nothing in `catena run`'s JSON changes for them.
TEST(CaseCli, DescriptionAndNotesReachTheReportOnly) {
  const std::string body =
      "[chain]\ntype = \"round-link\"\npitch = \"64 mm\"\nwire = \"18 mm\"\n"
      "[sprocket]\nteeth = 8\n[analyses.pocketwheel]\nomega = \"5 1/s\"\n";
  const std::string plain = write_case("prose_plain", body);
  const std::string prose =
      write_case("prose", "description = '''\nWhy this case.\n\nSecond paragraph.'''\n" + body +
                              "note = \"the free run-on\"\n");
  const fs::path out = fs::temp_directory_path() / "catena_prose.html";
  const CliRun r = run("report " + prose + " -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string html = read_text(out);
  EXPECT_NE(html.find("<section id=\"about\"><p>Why this case.</p><p>Second paragraph.</p>"),
            std::string::npos);
  EXPECT_NE(html.find("<div class=\"note\"><p>the free run-on</p></div>"), std::string::npos);
  EXPECT_EQ(html.find(">description<"), std::string::npos);  // not among the inputs
  EXPECT_EQ(html.find("analyses.pocketwheel.note"), std::string::npos);
  EXPECT_EQ(run_json("run " + prose)["analyses"], run_json("run " + plain)["analyses"]);
  fs::remove(out);
  fs::remove(prose);
  fs::remove(plain);
}

TEST(CaseCli, SharedValuesFeedEveryAnalysisThatTakesThem) {
  // chain.pitch reaches the hinge (dt/t) but the sweep, which refuses --pitch, does not get it
  const std::string path =
      write_case("shared", std::string(kHinge) +
                               "pitch = \"125 mm\"\n[analyses.hinge]\nplate_radius = \"20 mm\"\n"
                               "[analyses.hinge_sweep]\ncount = 5\n");
  const auto j = run_json("run " + path);
  EXPECT_TRUE(j["analyses"]["hinge"]["pitch_change"].contains("dt_over_t"));
  EXPECT_EQ(j["analyses"]["hinge_sweep"]["rows"].size(), 5u);
  fs::remove(path);
}

TEST(CaseCli, ChainTypeChoosesTheEngagementHingeAndItsSharedValues) {
  // a sliding-hinge case: [material] friction reaches the sliding engagement; the same values in
  // a rolling-hinge case would not (a rolling hinge refuses --friction on the command line)
  const std::string path =
      write_case("sliding",
                 "[chain]\ntype = \"sliding-hinge\"\npitch = \"125 mm\"\n[sprocket]\nteeth = 8\n"
                 "strokes = 2\n[loads]\ntension = \"29.4 kN\"\n[material]\nfriction = 0.15\n"
                 "[analyses.engagement]\n");
  const auto j = run_json("run " + path);
  const auto direct = run_json(
      "engagement --hinge sliding --pitch 125mm --teeth 8 --strokes 2 --tension 29.4kN "
      "--friction 0.15 --format json");
  EXPECT_EQ(j["analyses"]["engagement"], direct);
  EXPECT_EQ(j["analyses"]["engagement"]["hinge"], "sliding");
  fs::remove(path);
}

}  // namespace
