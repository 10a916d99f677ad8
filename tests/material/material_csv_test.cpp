// Material tables (CSV, version 1) against the specification in materials/README.md.
#include "fabform/material/material_csv.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fabform/error.hpp"
#include "test_paths.hpp"

namespace fabform::material_csv_test {
namespace {

const std::string kSource = "table.csv";

TensionTable parse(const std::string& text) {
  std::istringstream in(text);
  return parse_material_table(in, kSource);
}

// Parses text that must be rejected; returns the error (fails the test if none is thrown).
InputError parse_error(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError({}, "");
}

TEST(MaterialCsv, ParsesTensionTable) {
  const TensionTable table = parse("strain,tension_N_per_m\n0,0\n0.1,2.5\n0.5,30\n");
  ASSERT_EQ(table.points().size(), 3u);
  EXPECT_EQ(table.points()[1].strain, 0.1);
  EXPECT_EQ(table.points()[1].tension_N_per_m, 2.5);
  EXPECT_EQ(table.points()[2].tension_N_per_m, 30.0);
  EXPECT_TRUE(table.tension_only());
  EXPECT_EQ(table.name(), kSource);
}

TEST(MaterialCsv, StressTableIsMultipliedByThickness) {
  // The README's own example.
  const TensionTable table = parse(
      "# comments anywhere\nthickness_m,0.0005\nstrain,stress_Pa\n0,0\n0.1,2.0e5\n0.5,1.5e6\n");
  ASSERT_EQ(table.points().size(), 3u);
  // One multiplication, one rounding: compared with the same product.
  EXPECT_DOUBLE_EQ(table.points()[1].tension_N_per_m, 2.0e5 * 0.0005);
  EXPECT_DOUBLE_EQ(table.points()[2].tension_N_per_m, 1.5e6 * 0.0005);
  EXPECT_EQ(table.points()[2].strain, 0.5);
  EXPECT_NEAR(table.tension(0.3), 0.5 * (100.0 + 750.0), 1e-10);
}

TEST(MaterialCsv, NegativeStrainTableNeedNotStartAtZero) {
  const TensionTable table = parse("strain,tension_N_per_m\n-0.2,-4\n0.1,2\n");
  EXPECT_FALSE(table.tension_only());
  EXPECT_EQ(table.min_strain(), -0.2);
}

TEST(MaterialCsv, CommentsBlankLinesWhitespaceAndCrlf) {
  const std::string text =
      "# header comment\r\n"
      "\r\n"
      "   \t  \r\n"
      "  strain,tension_N_per_m  \r\n"
      "# between\r\n"
      "\t0 , 0\r\n"
      "\r\n"
      "  # indented comment\r\n"
      "0.1,\t1.5\r\n"
      "0.2 ,4";  // no final line terminator
  const TensionTable table = parse(text);
  ASSERT_EQ(table.points().size(), 3u);
  EXPECT_EQ(table.points()[1].tension_N_per_m, 1.5);
  EXPECT_EQ(table.points()[2].strain, 0.2);
  EXPECT_EQ(table.points()[2].tension_N_per_m, 4.0);
}

TEST(MaterialCsv, NumberForms) {
  // Examples from the spec: 0, -0.5, .25, 1., 2.5e-3, 1E+06; and 0.0,-0 as the first point.
  const TensionTable table = parse(
      "strain,tension_N_per_m\n0.0,-0\n2.5e-3,.25\n.5,1.\n1.,1E+06\n+2,+3e0\n");
  ASSERT_EQ(table.points().size(), 5u);
  EXPECT_EQ(table.points()[1].strain, 2.5e-3);
  EXPECT_EQ(table.points()[1].tension_N_per_m, 0.25);
  EXPECT_EQ(table.points()[2].strain, 0.5);
  EXPECT_EQ(table.points()[2].tension_N_per_m, 1.0);
  EXPECT_EQ(table.points()[3].tension_N_per_m, 1e6);
  EXPECT_EQ(table.points()[4].strain, 2.0);
  EXPECT_EQ(table.points()[4].tension_N_per_m, 3.0);
}

TEST(MaterialCsv, ReadsFileAndNamesItAfterThePath) {
  const std::string path = test::source_path("materials/white-swim-solid_warp.csv");
  const TensionTable table = read_material_table(path);
  EXPECT_EQ(table.name(), path);
  EXPECT_GT(table.points().size(), 10u);
}

// One malformed table: the text, and the 1-based line the error must name (0 = the error
// belongs to the whole file, e.g. a missing header in a file with no lines at all).
struct BadTable {
  const char* what;
  std::string text;
  int line;
};

void PrintTo(const BadTable& bad, std::ostream* os) { *os << bad.what; }

class MaterialCsvError : public ::testing::TestWithParam<BadTable> {};

TEST_P(MaterialCsvError, ThrowsInputErrorNamingSourceAndLine) {
  const BadTable& bad = GetParam();
  const InputError error = parse_error(bad.text);
  EXPECT_EQ(error.where().file, kSource) << bad.what;
  EXPECT_EQ(error.where().line, bad.line) << bad.what << ": " << error.what();
  const std::string prefix =
      bad.line > 0 ? kSource + ":" + std::to_string(bad.line) + ": " : kSource + ": ";
  EXPECT_EQ(std::string(error.what()).rfind(prefix, 0), 0u) << error.what();
  EXPECT_FALSE(error.message().empty());
}

const std::string kHeader = "strain,tension_N_per_m\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, MaterialCsvError,
    ::testing::Values(
        BadTable{"decreasing strain", kHeader + "0,0\n0.2,1\n0.1,2\n", 4},
        BadTable{"decreasing strain after comments", "# c\n\n" + kHeader + "0,0\n# c\n0.2,1\n\n0.1,2\n", 8},
        BadTable{"equal strains", kHeader + "0,0\n0.1,1\n0.1,2\n", 4},
        BadTable{"non-numeric strain", kHeader + "0,0\nabc,1\n", 3},
        BadTable{"non-numeric value", kHeader + "0,0\n0.1,1x\n", 3},
        BadTable{"empty cell", kHeader + "0,0\n0.1,\n", 3},
        BadTable{"NaN value", kHeader + "0,0\n0.1,nan\n", 3},
        BadTable{"NaN strain", kHeader + "0,0\nNaN,1\n", 3},
        BadTable{"inf value", kHeader + "0,0\n0.1,inf\n", 3},
        BadTable{"-infinity strain", kHeader + "-infinity,0\n0.1,1\n", 2},
        BadTable{"overflow to infinity", kHeader + "0,0\n0.1,1e400\n", 3},
        BadTable{"trailing comment", kHeader + "0,0\n0.1,2 # x\n", 3},
        BadTable{"thousands separator", kHeader + "0,0\n0.1,1,000\n", 3},
        BadTable{"three cells", kHeader + "0,0\n0.1,1,2\n0.2,3\n", 3},
        BadTable{"one cell", kHeader + "0,0\n0.1\n", 3},
        BadTable{"missing header (data first)", "0,0\n0.1,1\n", 1},
        BadTable{"missing header (empty file)", "", 0},
        BadTable{"missing header (comments only)", "# a\n\n# b\n", 0},
        BadTable{"header case", "Strain,tension_N_per_m\n0,0\n0.1,1\n", 1},
        BadTable{"unknown unit column", "# c\nstrain,tension_kN_per_m\n0,0\n0.1,1\n", 2},
        BadTable{"second header", kHeader + "0,0\n" + kHeader + "0.1,1\n", 3},
        BadTable{"stress without thickness", "# c\nstrain,stress_Pa\n0,0\n0.1,1e5\n", 2},
        BadTable{"thickness with tension", "thickness_m,0.001\n" + kHeader + "0,0\n0.1,1\n", 1},
        BadTable{"zero thickness", "thickness_m,0\nstrain,stress_Pa\n0,0\n0.1,1e5\n", 1},
        BadTable{"negative thickness", "\nthickness_m,-1e-3\nstrain,stress_Pa\n0,0\n0.1,1e5\n", 2},
        BadTable{"non-numeric thickness", "thickness_m,thin\nstrain,stress_Pa\n0,0\n0.1,1e5\n", 1},
        BadTable{"unknown directive", "density_kg_m2,0.2\n" + kHeader + "0,0\n0.1,1\n", 1},
        BadTable{"directive key case", "Thickness_m,0.001\nstrain,stress_Pa\n0,0\n0.1,1\n", 1},
        BadTable{"directive after header", "strain,stress_Pa\nthickness_m,0.001\n0,0\n0.1,1\n", 2},
        BadTable{"zero density", "areal_density_kg_m2,0\n" + kHeader + "0,0\n0.1,1\n", 1},
        BadTable{"negative density", "# c\nareal_density_kg_m2,-0.2\n" + kHeader + "0,0\n0.1,1\n", 2},
        BadTable{"NaN density", "areal_density_kg_m2,nan\n" + kHeader + "0,0\n0.1,1\n", 1},
        BadTable{"density twice", "areal_density_kg_m2,0.2\nareal_density_kg_m2,0.2\n" + kHeader + "0,0\n0.1,1\n", 2},
        BadTable{"density after header", kHeader + "areal_density_kg_m2,0.2\n0,0\n0.1,1\n", 2},
        BadTable{"tension-only not starting at 0,0", kHeader + "# c\n0,0.5\n0.1,1\n", 3},
        BadTable{"tension-only starting at strain 0.01", kHeader + "0.01,0\n0.1,1\n", 2},
        BadTable{"line too long", kHeader + "0,0\n0.1," + std::string(5000, '1') + "\n", 3}));

// The areal density directive, with either table kind; absent, the file states none.
TEST(MaterialCsv, ArealDensityDirective) {
  std::istringstream tension("areal_density_kg_m2,0.324\n" + kHeader + "0,0\n0.1,1\n");
  EXPECT_EQ(parse_material_file(tension, kSource).areal_density_kg_m2, 0.324);
  std::istringstream stress("thickness_m,0.001\nareal_density_kg_m2 , 2.5e-1\nstrain,stress_Pa\n0,0\n0.1,1e5\n");
  const MaterialFile file = parse_material_file(stress, kSource);
  EXPECT_EQ(file.areal_density_kg_m2, 0.25);
  EXPECT_DOUBLE_EQ(file.table.points()[1].tension_N_per_m, 100.0);
  std::istringstream none(kHeader + "0,0\n0.1,1\n");
  EXPECT_FALSE(parse_material_file(none, kSource).areal_density_kg_m2.has_value());
}

// The shipped tables carry their source's density (kg/m², materials/source/wang2011_berkeley).
// Where the force first falls with strain, for the scene to refuse unless softening is meant;
// compression that eases towards zero strain rises, so it is not falling.
TEST(MaterialCsv, FirstFallingPointIsFound) {
  std::istringstream falls("strain,tension_N_per_m\n0,0\n0.1,5\n# peak\n0.2,4\n0.3,3\n");
  EXPECT_EQ(parse_material_file(falls, kSource).falling_line, 5);
  std::istringstream rises("strain,tension_N_per_m\n-0.1,-2\n0,0\n0.1,5\n0.2,5\n");
  EXPECT_EQ(parse_material_file(rises, kSource).falling_line, 0);
}

TEST(MaterialCsv, ShippedTablesStateTheirSourcesDensity) {
  const std::vector<std::pair<std::string, double>> fabrics = {
      {"white-swim-solid", 0.204}, {"ivory-rib-knit", 0.276}, {"11oz-black-denim", 0.324}};
  for (const auto& [fabric, density] : fabrics)
    for (const char* direction : {"_warp.csv", "_weft.csv", "_shear.csv"})
      EXPECT_EQ(read_material_file(test::source_path("materials/" + fabric + direction)).areal_density_kg_m2,
                density) << fabric << direction;
}

// "A table needs at least two points" belongs to the whole table, not to one line: the error
// may name no line, or the line of the lone point; it must name the source.
TEST(MaterialCsv, FewerThanTwoPoints) {
  for (const std::string& text : {kHeader, kHeader + "0,0\n", kHeader + "# only\n0,0\n\n"}) {
    const InputError error = parse_error(text);
    EXPECT_EQ(error.where().file, kSource);
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    EXPECT_TRUE(error.where().line == 0 || (error.where().line >= 2 && error.where().line <= lines))
        << error.what();
  }
}

// Rules of the number grammar and directives (materials/README.md, lexical rules and
// structure 1), each with the line the error must name.

TEST(MaterialCsv, RejectsHexFloats) {
  EXPECT_EQ(parse_error(kHeader + "0,0\n0x1p-3,1\n").where().line, 3);
}

TEST(MaterialCsv, RejectsRepeatedDirective) {
  EXPECT_EQ(parse_error("thickness_m,0.001\nthickness_m,0.002\nstrain,stress_Pa\n0,0\n0.1,1e5\n")
                .where()
                .line,
            2);
}

// Only overflow to infinity is an error: 1e-400 reads as 0 (as in the reference reader,
// tools/derive_wang2011_tables.py), 1e-310 as a subnormal.
TEST(MaterialCsv, AcceptsNumbersThatUnderflow) {
  const TensionTable table = parse(kHeader + "0,0\n0.1,1e-400\n0.2,1e-310\n0.3,1\n");
  ASSERT_EQ(table.points().size(), 4u);
  EXPECT_EQ(table.points()[1].tension_N_per_m, 0.0);
  EXPECT_GT(table.points()[2].tension_N_per_m, 0.0);
  EXPECT_LT(table.points()[2].tension_N_per_m, 1e-300);
}

TEST(MaterialCsv, MissingFileNamesThePath) {
  const std::string path = test::source_path("materials/no_such_table.csv");
  try {
    read_material_table(path);
    FAIL() << "no InputError for a missing file";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, path);
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos);
  }
}

TEST(MaterialCsv, FileErrorNamesThePathAndLine) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("fabform_material_csv_test_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "bad.csv").string();
  {
    std::ofstream out(path, std::ios::binary);
    out << "# bad\r\nstrain,tension_N_per_m\r\n0,0\r\n0.2,1\r\n0.1,2\r\n";
  }
  try {
    read_material_table(path);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, path);
    EXPECT_EQ(error.where().line, 5);
    EXPECT_EQ(std::string(error.what()).rfind(path + ":5: ", 0), 0u) << error.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(MaterialCsv, EveryShippedTableLoadsTensionOnlyAndIncreasing) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("materials")))
    if (entry.path().extension() == ".csv") files.push_back(entry.path());
  EXPECT_EQ(files.size(), 9u);  // three fabrics × warp, weft, shear (materials/README.md)
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const TensionTable table = read_material_table(file.string());
    EXPECT_TRUE(table.tension_only());
    ASSERT_GE(table.points().size(), 2u);
    EXPECT_EQ(table.points().front().strain, 0.0);
    EXPECT_EQ(table.points().front().tension_N_per_m, 0.0);
    EXPECT_EQ(table.max_strain(), 1.0);  // the README: "the tables shipped here end at e = 1.0"
    for (std::size_t k = 1; k < table.points().size(); ++k) {
      EXPECT_GT(table.points()[k].strain, table.points()[k - 1].strain);
      EXPECT_GT(table.points()[k].tension_N_per_m, table.points()[k - 1].tension_N_per_m);
    }
  }
}

TEST(MaterialCsv, ShippedTablesMatchReadmeSummary) {
  // materials/README.md, "Summary": T at e = 0.05, 0.1667, 0.5, printed with 4 significant
  // digits; tolerance half a unit of the 4th digit.
  struct Row {
    const char* file;
    double t005, t01667, t05;
  };
  const Row rows[] = {{"white-swim-solid_warp.csv", 4.921, 17.01, 75.69},
                      {"white-swim-solid_weft.csv", 11.96, 52.45, 233.4},
                      {"ivory-rib-knit_warp.csv", 4.95, 22.09, 98.29},
                      {"ivory-rib-knit_weft.csv", 13.43, 107.3, 477.4},
                      {"11oz-black-denim_warp.csv", 23.07, 97.78, 435.1},
                      {"11oz-black-denim_weft.csv", 110.7, 443.1, 1972},
                      {"white-swim-solid_shear.csv", 5.69, 16.13, 40.11},
                      {"ivory-rib-knit_shear.csv", 7.451, 18.47, 36.87},
                      {"11oz-black-denim_shear.csv", 5.816, 22.9, 78.89}};
  for (const Row& row : rows) {
    SCOPED_TRACE(row.file);
    const TensionTable table = read_material_table(test::source_path(std::string("materials/") + row.file));
    const auto half_digit = [](double v) { return 0.5 * std::pow(10.0, std::floor(std::log10(v)) - 3); };
    EXPECT_NEAR(table.tension(0.05), row.t005, half_digit(row.t005));
    EXPECT_NEAR(table.tension(0.1667), row.t01667, half_digit(row.t01667));
    EXPECT_NEAR(table.tension(0.5), row.t05, half_digit(row.t05));
  }
}

}  // namespace
}  // namespace fabform::material_csv_test
