// `pyro analyze projection-error` and `pyro analyze stereo` end to end: the numbers they print
// against the library, the figure files (CSV always, PNG through Debian's matplotlib), and the
// refusals (exit status 2 naming the argument; exit 1 with a clear message when matplotlib is
// missing, the CSV files written regardless).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/io/png_file.h"
#include "engine/math/billboard_alignment.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string first_line(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  return line;
}

void expect_no_partial_files(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_NE(e.path().extension(), ".partial") << e.path();
}

TEST(PyroCliAlignment, ProjectionErrorAtOnePoint) {
  const auto r =
      test::run_pyro({"analyze", "projection-error", "--cx", "1", "--cy", "1", "--cz", "-3",
                      "--radius", "0.5", "--near", "1", "--interocular", "0.065", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  const glm::dvec3 c(1.0, 1.0, -3.0);
  const ProjectionError e = projection_error(c, 0.5, 1.0);
  const ParallaxError p = parallax_error(c, 0.5, 1.0, 0.065);
  EXPECT_DOUBLE_EQ(j["e_x"].get<double>(), e.e_x);
  EXPECT_DOUBLE_EQ(j["e_y"].get<double>(), e.e_y);
  EXPECT_DOUBLE_EQ(j["e_x_paper"].get<double>(), paper_eq11_e_x(c, 0.5, 1.0));
  EXPECT_DOUBLE_EQ(j["e_y_paper"].get<double>(), paper_eq12_e_y(c, 0.5, 1.0));
  EXPECT_DOUBLE_EQ(j["horizontal_parallax_error"].get<double>(), p.horizontal);
  EXPECT_DOUBLE_EQ(j["vertical_parallax_error"].get<double>(), p.vertical);
  // The sample point of docs/billboard_alignment.md.
  EXPECT_NEAR(j["e_x"].get<double>(), -0.0187898, 1e-7);
  EXPECT_NEAR(j["e_x_paper"].get<double>(), 0.0331575, 1e-7);
}

struct BadPoint {
  const char* label;
  std::vector<std::string> args;
  const char* expected;  // in the message
};

void PrintTo(const BadPoint& c, std::ostream* os) { *os << c.label; }

class PyroCliAlignmentBadPoint : public ::testing::TestWithParam<BadPoint> {};

TEST_P(PyroCliAlignmentBadPoint, RefusedWithExitTwo) {
  std::vector<std::string> args = {"analyze", "projection-error"};
  args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
  const auto r = test::run_pyro(args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(GetParam().expected), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    Mistakes, PyroCliAlignmentBadPoint,
    ::testing::Values(
        BadPoint{"behind",
                 {"--cx", "0", "--cy", "0", "--cz", "2", "--radius", "0.5", "--near", "1"},
                 "behind the camera"},
        BadPoint{"on_viewplane",
                 {"--cx", "0", "--cy", "0", "--cz", "-1", "--radius", "0.5", "--near", "1"},
                 "on the viewplane"},
        BadPoint{"before_viewplane",
                 {"--cx", "0", "--cy", "0", "--cz", "-0.5", "--radius", "0.1", "--near", "1"},
                 "between the viewpoint and the viewplane"},
        BadPoint{"edge_reaches_viewplane",
                 {"--cx", "3", "--cy", "0", "--cz", "-1.2", "--radius", "0.5", "--near", "1"},
                 "reaches the viewplane"},
        BadPoint{
            "missing_near", {"--cx", "0", "--cy", "0", "--cz", "-3", "--radius", "0.5"}, "--near"},
        BadPoint{"negative_near",
                 {"--cx", "0", "--cy", "0", "--cz", "-3", "--radius", "0.5", "--near", "-1"},
                 "--near"},
        BadPoint{
            "unknown_surface", {"--surface", "fig99", "--out", "/tmp/never_written"}, "--surface"},
        BadPoint{"surface_without_out", {"--surface", "fig4"}, "--out"},
        BadPoint{
            "surface_with_point", {"--surface", "fig4", "--out", "/tmp/x", "--cx", "1"}, "--cx"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(PyroCliAlignment, AllSurfacesAsCsv) {
  const fs::path out = test::scratch_dir("csv") / "figures";
  const auto r = test::run_pyro({"analyze", "projection-error", "--surface", "all", "--out",
                                 out.string(), "--grid", "9", "--csv-only", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  ASSERT_EQ(j["figures"].size(), 10u);
  EXPECT_FALSE(j["png"].get<bool>());
  const char* headers[] = {"c_x,c_y,c_z,e_x,e_x_paper",
                           "c_x,c_y,c_z,e_x,e_x_paper",
                           "point,x,y,z,x_star,y_star",
                           "point,x,y,z,x_star,y_star",
                           "c_x,c_y,c_z,e_y,e_y_paper",
                           "c_x,c_y,c_z,e_y,e_y_paper",
                           "c_x,c_y,c_z,horizontal_parallax_error,horizontal_parallax_error_paper",
                           "c_x,c_y,c_z,horizontal_parallax_error,horizontal_parallax_error_paper",
                           "c_x,c_y,c_z,vertical_parallax_error,vertical_parallax_error_paper",
                           "c_x,c_y,c_z,vertical_parallax_error,vertical_parallax_error_paper"};
  for (size_t k = 0; k < 10; ++k) {
    const auto& f = j["figures"][k];
    EXPECT_EQ(f["name"], "fig" + std::to_string(k + 4));
    EXPECT_NE(f["title"].get<std::string>().find("Figure " + std::to_string(k + 4) + ":"),
              std::string::npos);
    const fs::path csv = f["csv"].get<std::string>();
    ASSERT_TRUE(fs::exists(csv)) << csv;
    EXPECT_EQ(first_line(csv), headers[k]) << csv;
    EXPECT_FALSE(f.contains("png"));
  }
  EXPECT_TRUE(fs::exists(out / "alignment_figures.json"));
  expect_no_partial_files(out);
  for (const auto& e : fs::directory_iterator(out)) EXPECT_NE(e.path().extension(), ".png");

  // Figure 4's values are the library's: check every row.
  std::istringstream rows(read_all(j["figures"][0]["csv"].get<std::string>()));
  std::string line;
  std::getline(rows, line);
  int count = 0;
  while (std::getline(rows, line)) {
    double cx, cy, cz, ex, ex_paper;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf", &cx, &cy, &cz, &ex, &ex_paper), 5);
    EXPECT_EQ(cy, 0.0);
    EXPECT_DOUBLE_EQ(ex, projection_error({cx, cy, cz}, 0.4, 1.0).e_x);
    EXPECT_DOUBLE_EQ(ex_paper, paper_eq11_e_x({cx, cy, cz}, 0.4, 1.0));
    ++count;
  }
  EXPECT_EQ(count, 81);
}

TEST(PyroCliAlignment, SurfaceAsPng) {
  const fs::path out = test::scratch_dir("png");
  const auto r = test::run_pyro({"analyze", "projection-error", "--surface", "fig9", "--out",
                                 out.string(), "--grid", "11", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  ASSERT_EQ(j["figures"].size(), 1u);
  const fs::path png = j["figures"][0]["png"].get<std::string>();
  ASSERT_TRUE(fs::exists(png)) << png;
  const PngImage img = read_png(png.string());
  EXPECT_GT(img.width, 600);
  EXPECT_GT(img.height, 300);
  EXPECT_TRUE(fs::exists(j["figures"][0]["csv"].get<std::string>()));
  expect_no_partial_files(out);
}

TEST(PyroCliAlignment, MissingMatplotlibFailsClearlyAfterWritingTheCsv) {
  // A fake `matplotlib` package first on PYTHONPATH makes the import fail, as on a machine
  // without python3-matplotlib.
  const fs::path dir = test::scratch_dir("no_mpl");
  fs::create_directories(dir / "fake" / "matplotlib");
  std::ofstream(dir / "fake" / "matplotlib" / "__init__.py")
      << "raise ImportError('simulated: no matplotlib here')\n";
  const char* old = std::getenv("PYTHONPATH");
  const std::string saved = old ? old : "";
  setenv("PYTHONPATH", (dir / "fake").c_str(), 1);
  const fs::path out = dir / "figures";
  const auto r = test::run_pyro(
      {"analyze", "projection-error", "--surface", "fig5", "--out", out.string(), "--grid", "5"});
  if (old)
    setenv("PYTHONPATH", saved.c_str(), 1);
  else
    unsetenv("PYTHONPATH");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("matplotlib"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("python3-matplotlib"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("CSV files are written"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out / "fig05_e_x_over_cx_cy.csv"));
  EXPECT_FALSE(fs::exists(out / "fig05_e_x_over_cx_cy.png"));
  expect_no_partial_files(out);
}

TEST(PyroCliAlignment, StereoAnalysis) {
  const auto r = test::run_pyro(
      {"analyze", "stereo", "--eye", "3", "2.5", "7", "--target", "-1", "1", "0", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  EXPECT_EQ(j["points"], 21 * 21 * 21);
  EXPECT_EQ(j["width"], 1024);
  EXPECT_EQ(j["height"], 768);
  EXPECT_LE(j["max_vertical_parallax"].get<double>(), 1e-6);
  EXPECT_LE(j["max_horizontal_parallax_error"].get<double>(), 1e-6);
  for (const char* eye : {"left", "right"}) {
    ASSERT_EQ(j[eye]["view"].size(), 4u);
    ASSERT_EQ(j[eye]["projection"].size(), 4u);
    EXPECT_EQ(j[eye]["view"][3], nlohmann::json({0.0, 0.0, 0.0, 1.0}));
    EXPECT_EQ(j[eye]["projection"][3][2].get<double>(), -1.0);
  }
  // Off-axis: the projections differ in the x shear only, with opposite signs.
  EXPECT_FLOAT_EQ(j["left"]["projection"][0][2].get<float>(),
                  -j["right"]["projection"][0][2].get<float>());

  const auto zero = test::run_pyro({"analyze", "stereo", "--interocular", "0", "--json"});
  ASSERT_EQ(zero.exit_code, 0) << zero.err;
  const auto z = test::last_json_line(zero.out);
  EXPECT_EQ(z["max_vertical_parallax"].get<double>(), 0.0);
  EXPECT_EQ(z["horizontal_parallax_range"], nlohmann::json({0.0, 0.0}));

  EXPECT_EQ(test::run_pyro({"analyze", "stereo", "--near", "5", "--far", "1"}).exit_code, 2);
  EXPECT_EQ(test::run_pyro({"analyze", "stereo", "--zero-parallax", "0"}).exit_code, 2);
  EXPECT_EQ(test::run_pyro({"analyze", "stereo", "--eye", "0", "0", "0", "--target", "0", "5", "0"})
                .exit_code,
            2);
}

}  // namespace
}  // namespace pyro
