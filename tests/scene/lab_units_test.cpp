// A textile lab's units in a scene: areal mass in g/m², flexural rigidity per direction in µN·m
// or as a cantilever's bending length, shear rigidity G as FAST or KES give it, and the Cusick
// tester's clamp. Each is checked against its definition, not against fabform's own numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "fabform/model/gravity.hpp"
#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/hinge_friction.hpp"
#include "fabform/model/shear_friction.hpp"
#include "fabform/model/potential_energy.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "support/scene_models.hpp"
#include "support/temp_dir.hpp"
#include "support/terms.hpp"

namespace fabform::lab_units_test {
namespace {

class LabUnits : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("table.csv", "strain,tension_N_per_m\n0,0\n1,500\n");
    dir.write("heavy.csv", "areal_density_kg_m2,0.25\nstrain,tension_N_per_m\n0,0\n1,500\n");
  }
  // A 10 × 5 cm rectangle, held along its left edge; `extra` adds tables.
  std::string scene(const std::string& fabric_keys, const std::string& extra,
                    const std::string& table = "table.csv") const {
    return "[fabric]\nsize_m = [0.1, 0.05]\ndivisions = [10, 5]\nwarp = \"" + table + "\"\nweft = \"" + table +
           "\"\n" + fabric_keys + "[[constraint]]\nnodes = \"edge:left\"\n" + extra;
  }
  Model build(const std::string& text) const { return test::build_scene(dir, text); }
  InputError error(const std::string& text) const { return test::scene_error(dir, text); }
  test::TempDir dir;
};

double total_weight_N(const Model& model) {
  double total = 0.0;
  for (const Eigen::Vector3d& f : test::find_term<Gravity>(model)->loads()) total += f.z();
  return -total;
}

TEST_F(LabUnits, ArealMassInGramsPerSquareMetreWeighsTheFabric) {
  const Model model = build(scene("areal_mass_g_m2 = 192\n", "[gravity]\n"));
  const double area = 0.1 * 0.05;
  EXPECT_NEAR(total_weight_N(model), 0.192 * area * kStandardGravity_m_s2, 1e-12 * 0.192 * area * 9.81);
  EXPECT_DOUBLE_EQ(model.areal_density_kg_m2, 0.192);
}

// The same mass in the table (kg/m²) and the scene (g/m²) is accepted; a different one is bad
// input on the scene's line, and the message names the table's file and line.
TEST_F(LabUnits, ArealMassMustAgreeWithTheTables) {
  EXPECT_DOUBLE_EQ(build(scene("areal_mass_g_m2 = 250\n", "[gravity]\n", "heavy.csv")).areal_density_kg_m2, 0.25);
  const InputError e = error(scene("areal_mass_g_m2 = 204\n", "[gravity]\n", "heavy.csv"));
  EXPECT_EQ(e.where().line, 6) << e.what();
  EXPECT_EQ(e.where().key, "fabric.areal_mass_g_m2") << e.what();
  EXPECT_NE(std::string(e.what()).find("differs from the material file's 250 g/m²"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("heavy.csv line 1"), std::string::npos) << e.what();
}

// Dynamic's own mass is for a fabric that has none; given beside the fabric's, it would be ignored.
TEST_F(LabUnits, DynamicsMassBesideTheFabricsIsRefused) {
  const InputError e = error(scene("areal_mass_g_m2 = 200\n", "[solver]\nareal_density_kg_m2 = 0.3\n"));
  EXPECT_EQ(e.where().key, "solver.areal_density_kg_m2") << e.what();
  EXPECT_NE(std::string(e.what()).find("fabric.areal_mass_g_m2"), std::string::npos) << e.what();
  const InputError g = error(scene("", "[gravity]\n[solver]\nareal_density_kg_m2 = 0.3\n", "heavy.csv"));
  EXPECT_NE(std::string(g.what()).find("material files"), std::string::npos) << g.what();
}

const HingeBending& hinges(const Model& model) {
  const HingeBending* term = test::find_term<HingeBending>(model);
  if (!term) throw std::logic_error("no hinges");
  return *term;
}

// The hinge of a side along the weft (x constant) bends the warp, and takes the warp's rigidity.
double rigidity_across(const Model& model, bool side_along_weft) {
  for (const Hinge& h : model.fabric.hinges()) {
    const Eigen::Vector3d e = model.fabric.rest_position(h.edge[1]) - model.fabric.rest_position(h.edge[0]);
    if ((std::abs(e.x()) < 1e-12) == side_along_weft) return hinges(model).rigidity_of(model, h);
  }
  throw std::logic_error("no such hinge");
}

TEST_F(LabUnits, RigidityInMicroNewtonMetresPerDirection) {
  const Model model = build(scene("", "[bending]\nrigidity_uNm = [12.5, 4]\n"));
  EXPECT_DOUBLE_EQ(rigidity_across(model, true), 12.5e-6);
  EXPECT_DOUBLE_EQ(rigidity_across(model, false), 4e-6);
  const Model same = build(scene("", "[bending]\nrigidity_uNm = 7\n"));
  EXPECT_DOUBLE_EQ(rigidity_across(same, true), 7e-6);
  EXPECT_DOUBLE_EQ(rigidity_across(same, false), 7e-6);
}

// Between the two directions the rule is B_warp·cos²ψ + B_weft·sin²ψ: a hinge across a side at
// 45° (an arc mesh's spoke on the diagonal) takes their mean.
TEST_F(LabUnits, DiagonalHingeTakesTheMeanRigidity) {
  const Model model = build("[fabric]\nshape = \"circle\"\ndiameter_m = 0.1\nmesh = \"arc\"\nrings = 3\nspokes = 8\n"
                            "warp = \"table.csv\"\nweft = \"table.csv\"\n[bending]\nrigidity_uNm = [10, 2]\n");
  int diagonal = 0;
  for (const Hinge& h : model.fabric.hinges()) {
    const Eigen::Vector3d e = model.fabric.rest_position(h.edge[1]) - model.fabric.rest_position(h.edge[0]);
    if (std::abs(std::abs(e.x()) - std::abs(e.y())) > 1e-12 * e.norm()) continue;
    EXPECT_NEAR(hinges(model).rigidity_of(model, h), 6e-6, 1e-15);
    ++diagonal;
  }
  EXPECT_GT(diagonal, 0);
}

// BS 3356 / ASTM D1388: a strip's bending length c and its weight per area m·g₀ give B = m·g₀·c³.
TEST_F(LabUnits, BendingLengthGivesTheCantileverRigidity) {
  const Model model = build(scene("areal_mass_g_m2 = 180\n", "[bending]\nbending_length_cm = [2.5, 1.5]\n"));
  EXPECT_NEAR(rigidity_across(model, true), 0.18 * 9.80665 * std::pow(0.025, 3), 1e-12 * 2.8e-5);
  EXPECT_NEAR(rigidity_across(model, false), 0.18 * 9.80665 * std::pow(0.015, 3), 1e-12 * 6e-6);
  const Model from_table = build(scene("", "[bending]\nbending_length_cm = 2\n", "heavy.csv"));
  EXPECT_NEAR(rigidity_across(from_table, true), 0.25 * 9.80665 * 8e-6, 1e-12 * 2e-5);
}

TEST_F(LabUnits, BendingLengthWithoutAMassIsRefusedAtItsKey) {
  const InputError e = error(scene("", "[bending]\nbending_length_cm = 2\n"));
  EXPECT_EQ(e.where().key, "bending.bending_length_cm") << e.what();
  EXPECT_NE(std::string(e.what()).find("fabric.areal_mass_g_m2"), std::string::npos) << e.what();
}

// KES-FB's 2HB in gf·cm/cm (1 gf·cm/cm = 9.80665e-3 N·m/m), per direction: the warp's across
// sides along the weft, as the rigidity; the hinges bend against half of it.
TEST_F(LabUnits, BendingHysteresisInGramForceCentimetresPerCentimetre) {
  const Model model = build(scene("", "[bending]\nrigidity_uNm = 7\nhysteresis_gf_cm_cm = [0.08, 0.02]\n"));
  const HingeFriction* friction = test::find_term<HingeFriction>(model);
  ASSERT_NE(friction, nullptr);
  for (const Hinge& h : model.fabric.hinges()) {
    const Eigen::Vector3d e = model.fabric.rest_position(h.edge[1]) - model.fabric.rest_position(h.edge[0]);
    const double two_hb = std::abs(e.x()) < 1e-12 ? 0.08 : 0.02;
    EXPECT_NEAR(friction->friction_moment_of(model, h), 0.5 * two_hb * 9.80665e-3, 1e-15);
  }
  const Model si = build(scene("", "[bending]\nrigidity_uNm = 7\nhysteresis_Nm_m = 5e-4\n"));
  EXPECT_NEAR(test::find_term<HingeFriction>(si)->friction_moment_of(si, si.fabric.hinges()[0]), 2.5e-4, 1e-18);
  EXPECT_EQ(test::find_term<HingeFriction>(build(scene("", "[bending]\nrigidity_uNm = 7\n"))), nullptr);
}

// Friction acts in hinges: seed 004's bend springs have none, and the refusal names the key.
TEST_F(LabUnits, BendingHysteresisNeedsHinges) {
  const InputError e = error(scene("", "[bending]\nstiffness_N_m = 0.5\nhysteresis_gf_cm_cm = 0.05\n"));
  EXPECT_EQ(e.where().key, "bending.hysteresis_gf_cm_cm") << e.what();
  EXPECT_EQ(e.where().line, 10) << e.what();
  EXPECT_NE(std::string(e.what()).find("rigidity_uNm"), std::string::npos) << e.what();
}

// Dynamic's fabric would swing back along the loading branch as if it were elastic: refused at the
// solver's name.
TEST_F(LabUnits, BendingHysteresisIsRefusedInDynamic) {
  const InputError e = error(scene("", "[bending]\nrigidity_uNm = 7\nhysteresis_gf_cm_cm = 0.05\n"
                                       "[solver]\nname = \"dynamic\"\n"));
  EXPECT_EQ(e.where().key, "solver.name") << e.what();
  EXPECT_NE(std::string(e.what()).find("loading branch"), std::string::npos) << e.what();
}

// In load steps a fabric the tool straightens again would spring back along the loading branch:
// refused at the friction's key, naming the travelling body and where its steps were given.
TEST_F(LabUnits, HysteresisIsRefusedInLoadSteps) {
  dir.write("plate.obj", "v 0 0 -0.01\nv 0.2 0 -0.01\nv 0 0.2 -0.01\nf 1 2 3\n");
  const std::string travelling = "[[body]]\nname = \"punch\"\nmesh = \"plate.obj\"\nunits = \"m\"\n[body.path]\nsteps = 4\n"
                                 "translation_m = [0, 0, 0.01]\n";
  for (const auto& [section, key] : {std::pair<std::string, std::string>{"[bending]\nrigidity_uNm = 7\n", "bending.hysteresis_gf_cm_cm = 0.05"},
                                     {"[shear]\nrigidity_N_m = 40\n", "shear.hysteresis_gf_cm = 1.5"}}) {
    const std::string name = key.substr(key.find('.') + 1);
    const InputError e = error(scene("", section + name + "\n" + travelling));
    EXPECT_EQ(e.where().key, key.substr(0, key.find(' '))) << e.what();
    EXPECT_EQ(e.where().line, 10) << e.what();
    EXPECT_NE(std::string(e.what()).find("body 'punch' travels in load steps (line 16)"), std::string::npos) << e.what();
  }
}

// A square cell sheared by a small γ stores the continuum's G·γ²/2 per area through its two
// diagonals; the warp and weft springs keep their length to second order and add only O(γ⁴).
double shear_energy_J(const Model& model, double gamma) {
  Positions x = model.start;
  for (Eigen::Vector3d& p : x) p.x() += gamma * p.y();
  return potential_energy(model, x) - potential_energy(model, model.start);
}

TEST_F(LabUnits, ShearRigidityStoresTheContinuumShearEnergy) {
  const double area = 0.1 * 0.05, gamma = 1e-4;
  for (const auto& [keys, g] : {std::pair<std::string, double>{"rigidity_N_m = 40", 40.0},
                                {"rigidity_gf_cm_deg = 0.8", 0.8 * 9.80665e-3 / 0.01 * 180.0 / M_PI}}) {
    const Model model = build(scene("", "[shear]\n" + keys + "\n"));
    // Relative error of the small-strain expansion: O(γ) from the diagonals' (1 + ε)² length.
    EXPECT_NEAR(shear_energy_J(model, gamma), 0.5 * g * gamma * gamma * area, 1e-3 * 0.5 * g * gamma * gamma * area)
        << keys;
  }
}

// KES-FB1's shear test read off the energy: the shear force per width a fabric sheared by γ holds,
// T = (1/A)·dE/dγ, follows the loop's loading branch G·γ + HG past the rounding γ₀ = 0.1°, HG =
// 2HG / 2 with 2HG in gf/cm × 0.980665 = N/m, and G·γ + HG·γ/γ₀ inside it (the stick).
TEST_F(LabUnits, ShearHysteresisFollowsTheKesLoadingBranch) {
  const double area = 0.1 * 0.05, g = 40.0, hg = 0.5 * 1.5 * 0.980665, rounding = 0.1 * M_PI / 180.0;
  for (const std::string& keys : {std::string("hysteresis_gf_cm = 1.5"), std::string("hysteresis_N_m = 1.4709975")}) {
    const Model model = build(scene("", "[shear]\nrigidity_N_m = 40\n" + keys + "\n"));
    for (const double gamma : {0.01, 0.03, 0.5 * rounding}) {
      const double h = 1e-3 * std::min(gamma, rounding);
      const double traction = (shear_energy_J(model, gamma + h) - shear_energy_J(model, gamma - h)) / (2.0 * h * area);
      // The weft springs (500 N/m), stretched by γ²/2 in simple shear, store 500·γ⁴/8 per area:
      // 500·γ³/2 more; the diagonals' strains are ±γ/2 + γ²/8, which adds O(γ³) to T.
      const double expected = g * gamma + hg * std::min(gamma / rounding, 1.0) + 0.5 * 500.0 * std::pow(gamma, 3);
      EXPECT_NEAR(traction, expected, 1e-3 * expected) << keys << " γ = " << gamma;
    }
  }
}

// Friction in shear reads a cell's shear from its diagonals, exact on a lattice's rectangles only:
// refused on a jittered mesh at its key, and in dynamic at the solver, saying where it was given.
TEST_F(LabUnits, ShearHysteresisIsRefusedWhereItCannotAct) {
  const InputError dynamic = error(scene("", "[shear]\nrigidity_N_m = 40\nhysteresis_gf_cm = 1.5\n"
                                             "[solver]\nname = \"dynamic\"\n"));
  EXPECT_EQ(dynamic.where().key, "solver.name") << dynamic.what();
  EXPECT_NE(std::string(dynamic.what()).find("shear friction (line 10)"), std::string::npos) << dynamic.what();
  const InputError jittered = error("[fabric]\nshape = \"circle\"\ndiameter_m = 0.1\nmesh = \"jittered\"\n"
                                    "divisions = 8\njitter = 0.15\nwarp = \"table.csv\"\nweft = \"table.csv\"\n"
                                    "[shear]\nmaterial = \"table.csv\"\nhysteresis_gf_cm = 1.5\n");
  EXPECT_EQ(jittered.where().key, "shear.hysteresis_gf_cm") << jittered.what();
  EXPECT_EQ(jittered.where().line, 11) << jittered.what();
  EXPECT_NE(std::string(jittered.what()).find("not \"jittered\""), std::string::npos) << jittered.what();
  const Model triangles = build("[fabric]\nshape = \"circle\"\ndiameter_m = 0.1\nmesh = \"triangular\"\n"
                                "divisions = 8\nwarp = \"table.csv\"\nweft = \"table.csv\"\n[shear]\n"
                                "material = \"table.csv\"\nhysteresis_gf_cm = 1.5\n");
  EXPECT_NE(test::find_term<ShearFriction>(triangles), nullptr);
}

// A tension-only shear table's diagonals, once compressed ones push back, carry half the table
// each: a small pure shear stores what it stored with the stretched diagonal alone, and a cell
// squeezed along its bias (by ε, the other bias unstrained) now resists through its diagonals.
TEST_F(LabUnits, CompressionKeepsTheShearRigidityAndResistsBiasSqueeze) {
  dir.write("shear.csv", "strain,tension_N_per_m\n0,0\n1,80\n");
  const auto model_with = [&](const std::string& compression) {
    return build(scene("compression = \"" + compression + "\"\n", "[shear]\nmaterial = \"shear.csv\"\n"));
  };
  const Model slack = model_with("none"), pushing = model_with("linear");
  const double gamma = 1e-4;
  EXPECT_NEAR(shear_energy_J(pushing, gamma), shear_energy_J(slack, gamma), 1e-3 * shear_energy_J(slack, gamma));
  // Squeezed along the bias: x·(1 − ε/2) − y·ε/2 and y·(1 − ε/2) − x·ε/2 shorten the 45° diagonal by ε.
  const auto squeeze_energy = [](const Model& model, double eps) {
    Positions x = model.start;
    for (std::size_t k = 0; k < x.size(); ++k) {
      const Eigen::Vector3d p = model.start[k];
      x[k].x() = p.x() - 0.5 * eps * (p.x() + p.y());
      x[k].y() = p.y() - 0.5 * eps * (p.x() + p.y());
    }
    return potential_energy(model, x) - potential_energy(model, model.start);
  };
  const double eps = 1e-4, area = 0.1 * 0.05;
  // The warp and weft (500 N/m, compressed by ε/2, linear both ways here) store 2·½·500·(ε/2)²
  // per area; the 45° diagonals at half the shear table (40 N/m) add ½·40·ε².
  EXPECT_NEAR(squeeze_energy(pushing, eps), (0.25 * 500 + 0.5 * 40) * eps * eps * area,
              2e-3 * (0.25 * 500 + 0.5 * 40) * eps * eps * area);
}

TEST_F(LabUnits, ShearNeedsExactlyOneSource) {
  const InputError both = error(scene("", "[shear]\nrigidity_N_m = 40\nrigidity_gf_cm_deg = 1\n"));
  EXPECT_NE(std::string(both.what()).find("give one of material"), std::string::npos) << both.what();
  const InputError bad = error(scene("", "[shear]\nrigidity_gf_cm_deg = -1\n"));
  EXPECT_EQ(bad.where().key, "shear.rigidity_gf_cm_deg") << bad.what();
}

// The clamp holds every node within its radius of the specimen's centre, in x, y and z, and no
// other: checked against the flat positions one by one.
TEST_F(LabUnits, CusickClampHoldsTheDiscOfNodes) {
  const std::string circle = "[fabric]\nshape = \"circle\"\ndiameter_m = 0.3\nmesh = \"quadrangular\"\ndivisions = 30\n"
                             "warp = \"table.csv\"\nweft = \"table.csv\"\n[drape]\nclamp_radius_m = 0.09\n";
  const Model model = build(circle);
  int held = 0;
  for (int k = 0; k < model.node_count(); ++k) {
    const double r = (model.fabric.rest_position(k).head<2>() - Eigen::Vector2d(0.15, 0.15)).norm();
    const AxisMask lock = model.locks[static_cast<std::size_t>(k)];
    EXPECT_EQ(lock, r <= 0.09 + 1e-12 ? kLockX | kLockY | kLockZ : 0) << model.fabric.node_name(k) << " at " << r;
    held += lock != 0;
  }
  EXPECT_GT(held, 100);  // π·9²/1² ≈ 254 lattice points of 1 cm
}

TEST_F(LabUnits, ClampAsWideAsTheSpecimenIsRefused) {
  const std::string circle = "[fabric]\nshape = \"circle\"\ndiameter_m = 0.3\nmesh = \"arc\"\nrings = 5\nspokes = 12\n"
                             "warp = \"table.csv\"\nweft = \"table.csv\"\n[drape]\nclamp_radius_m = 0.15\n";
  const InputError e = error(circle);
  EXPECT_EQ(e.where().line, 10) << e.what();
  EXPECT_EQ(e.where().key, "drape.clamp_radius_m") << e.what();
  EXPECT_NE(std::string(e.what()).find("not smaller than the specimen's radius 0.15 m"), std::string::npos) << e.what();
}

// The two slips: a weight in g/m² typed as kg/m², a rigidity in µN·m typed as N·m.
TEST_F(LabUnits, ValuesNoFabricHasAreWarnedWithTheRange) {
  dir.write("slip.csv", "areal_density_kg_m2,192\nstrain,tension_N_per_m\n0,0\n1,500\n");
  const Model heavy = build(scene("", "[gravity]\n", "slip.csv"));
  ASSERT_EQ(heavy.read_warnings.size(), 1u);
  EXPECT_NE(heavy.read_warnings[0].find("slip.csv:1: the areal mass 1.92e+05 g/m² lies outside the range of real "
                                        "fabrics, 5 to 3000 g/m²"),
            std::string::npos)
      << heavy.read_warnings[0];
  const Model stiff = build(scene("", "[bending]\nrigidity_Nm = 7\n"));
  ASSERT_EQ(stiff.read_warnings.size(), 2u);  // warp and weft
  EXPECT_NE(stiff.read_warnings[0].find(":9: bending.rigidity_Nm: the warp's flexural rigidity 7e+06 µN·m"),
            std::string::npos)
      << stiff.read_warnings[0];
  EXPECT_TRUE(build(scene("areal_mass_g_m2 = 200\n", "[bending]\nrigidity_uNm = 7\n[gravity]\n")).read_warnings.empty());
}

// Two unit slips: 2HB 0.05 gf·cm/cm typed in N·m/m (4.9e-4) into the lab's key, 2HG 1.5 gf/cm typed
// per metre (150 gf/m).
TEST_F(LabUnits, HysteresisNoFabricHasIsWarnedWithTheRange) {
  const Model slipped = build(scene("", "[bending]\nrigidity_uNm = 7\nhysteresis_gf_cm_cm = [4.9e-4, 0.05]\n"
                                        "[shear]\nrigidity_N_m = 40\nhysteresis_gf_cm = 150\n"));
  ASSERT_EQ(slipped.read_warnings.size(), 2u);
  EXPECT_NE(slipped.read_warnings[0].find(":10: bending.hysteresis_gf_cm_cm: the warp's bending hysteresis 2HB 0.00049 "
                                          "gf·cm/cm lies outside the range of real fabrics, 0.0005 to 20 gf·cm/cm"),
            std::string::npos)
      << slipped.read_warnings[0];
  EXPECT_NE(slipped.read_warnings[1].find(":13: shear.hysteresis_gf_cm: the shear hysteresis 2HG 150 gf/cm lies "
                                          "outside the range of real fabrics, 0.01 to 100 gf/cm"),
            std::string::npos)
      << slipped.read_warnings[1];
  EXPECT_TRUE(build(scene("", "[bending]\nrigidity_uNm = 7\nhysteresis_gf_cm_cm = 0.05\n[shear]\nrigidity_N_m = 40\n"
                              "hysteresis_gf_cm = 1.5\n")).read_warnings.empty());
  // A direction without friction (2HB = 0) is not a value to check.
  EXPECT_TRUE(build(scene("", "[bending]\nrigidity_uNm = 7\nhysteresis_gf_cm_cm = [0.05, 0]\n")).read_warnings.empty());
}

}  // namespace
}  // namespace fabform::lab_units_test
