// Every error a user can make in a case ends the run before the first step with a message
// naming the file, the keyword and what is expected.
#include "core/FatalError.hpp"
#include "driver/Simulation.hpp"
#include "generation/ParticleGenerator.hpp"
#include "io/ParticleFile.hpp"
#include "kernels/Kernel.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <limits>
#include <string>

using namespace sph::test;

namespace {

// The FatalError message of generating and running the case ("" if it succeeds).
std::string failureOf(const std::filesystem::path& dir, bool generate = true) {
    try {
        if (generate) sph::generateParticles(dir, true);
        sph::runCase(dir);
    } catch (const sph::FatalError& e) {
        return e.what();
    }
    return "";
}

// The dam break at dx = a/20 (800 fluid particles) to `endTime`, its 0/ generated.
std::filesystem::path coarseDamBreak(const std::string& endTime) {
    const auto dir = copyCase("damBreak2D");
    setEntry(dir / "system/generateParticlesDict", "spacing", "0.0028575");
    setEntry(dir / "system/controlDict", "endTime", endTime);
    sph::generateParticles(dir, false);
    return dir;
}

void expectContains(const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << "message:\n" << message << "\nexpected to contain:\n" << part;
}

}  // namespace

TEST(BadInput, MissingDictionary) {
    const auto dir = copyCase("damBreak2D");
    std::filesystem::remove(dir / "system/sphSchemes");
    expectContains(failureOf(dir), "error: cannot open dictionary '" + (dir / "system/sphSchemes").string() + "': file not found");
}

TEST(BadInput, SyntaxErrorNamesFileLineAndColumn) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/timeIntegration", "courant     0.2;", "courant     0.2");
    expectContains(failureOf(dir), (dir / "system/timeIntegration").string() + ":2:1: error: entry 'courant' is not terminated by ';'");
}

TEST(BadInput, UnknownModelListsTheValidNames) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/sphSchemes", "type wendlandC2;", "type wendland;");
    expectContains(failureOf(dir), (dir / "system/sphSchemes").string() +
                                       ":1:28: error: unknown kernel 'wendland'; valid kernel names are:\n    cubicSpline\n    quinticSpline\n"
                                       "    wendlandC2\n    wendlandC4\n    wendlandC6");
}

TEST(BadInput, KernelThisBuildDidNotCompile) {
    // Only a build with SPHKIT_KERNELS restricted has one (./Alltest's sanitizer build does).
    if (sph::compiledKernel<sph::WendlandC6<2>>) GTEST_SKIP() << "this build compiles every kernel";
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/sphSchemes", "type wendlandC2;", "type wendlandC6;");
    expectContains(failureOf(dir), (dir / "system/sphSchemes").string() +
                                       ":1:23: error: keyword 'type' in dictionary 'sphSchemes/kernel': kernel 'wendlandC6' is not compiled "
                                       "into this build (CMake option SPHKIT_KERNELS); compiled kernels: " +
                                       std::string(sph::compiledKernelNames));
}

TEST(BadInput, UnknownBoundaryModel) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "constant/boundaryProperties", "dummyParticles", "ghostParticles");
    expectContains(
        failureOf(dir),
        "error: unknown boundary model 'ghostParticles'; valid boundary model names are:\n    deficiencyCorrection\n"
        "    deficiencyCorrectionBoundaryIntegral\n    dummyParticles\n    dynamicBoundary\n    lennardJones\n    modifiedDynamicBoundary\n"
        "    monaghanKajtar");
}

TEST(BadInput, CorrectionWithAnUnknownPartner) {
    const auto dir = copyCase("rectangularTank2D");
    writeFile(dir / "constant/boundaryProperties", "tank { type deficiencyCorrection; repulsion { type springs; } }\n");
    expectContains(failureOf(dir),
                   "error: unknown repulsion 'springs'; valid repulsion names are:\n    lennardJones\n    monaghanKajtar\n    wallDistance");
}

TEST(BadInput, WallForceModelOnLayersOfWallParticles) {
    // Dummy particles' four layers under a wall-force model: each layer would push the fluid.
    const auto dir = copyCase("hydrostaticTank2D");
    writeFile(dir / "constant/boundaryProperties", "tank { type deficiencyCorrection; }\n");
    expectContains(failureOf(dir),
                   "error: keyword 'type' in dictionary 'boundaryProperties/tank': 'deficiencyCorrection' acts from one layer of wall "
                   "particles on the wall surface, but patch 'tank' has 4 layers; generate it with layers 1; firstLayerOffset 0;");
}

TEST(BadInput, DummyParticlesOnTooFewLayers) {
    // The quintic spline's support 3.6 dx needs 4 layers behind the wall.
    const auto dir = copyCase("hydrostaticTank2D");
    replaceInFile(dir / "system/generateParticlesDict", "layers 4;", "layers 1;");
    expectContains(failureOf(dir),
                   "error: keyword 'type' in dictionary 'boundaryProperties/tank': 'dummyParticles' needs at least 4 layers of wall "
                   "particles to fill the kernel support (0.072 = 3.6 dx) behind the wall, but patch 'tank' has 1;");
}

TEST(BadInput, PatchWithoutAModel) {
    const auto dir = copyCase("damBreak2D");
    writeFile(dir / "constant/boundaryProperties", "// no entry for the tank\n");
    expectContains(failureOf(dir), "error: keyword 'tank' is missing from dictionary 'boundaryProperties'");
}

TEST(BadInput, CoincidentWallPointsHaveNoNormal) {
    const auto dir = copyCase("deformingTank2D");
    replaceInFile(dir / "system/generateParticlesDict", "points ((0 1) (0 0) (2 0) (2 1))", "points ((0 1) (0 0) (0 0) (2 1))");
    expectContains(failureOf(dir), "error: keyword 'points' in dictionary 'generateParticlesDict/boundaries/tank': points 1 and 2 coincide");
}

TEST(BadInput, MotionTableShorterThanTheRun) {
    const auto dir = copyCase("deformingTank2D");
    writeFile(dir / "constant/motion.csv", "0 0 0\n1 0 0.01\n");
    replaceInFile(dir / "constant/boundaryProperties", "motion      { type gaussianBulge; centre (1 0); amplitude 0.1; width 0.2; period 2; }",
                  "motion      { type table; file \"constant/motion.csv\"; }");
    expectContains(failureOf(dir), "motion.csv' covers t from 0 to 1, but the run goes from 0 to 2");
}

TEST(BadInput, BodyWithoutPositiveMass) {
    const auto dir = copyCase("sinkingCylinder2D");
    replaceInFile(dir / "constant/boundaryProperties", "mass 62.832;", "mass 0;");
    expectContains(failureOf(dir), "error: keyword 'mass' in dictionary 'boundaryProperties/cylinder/motion': must be greater than zero, found 0");
}

TEST(BadInput, FreeBodyNeedsAWallForceModel) {
    const auto dir = copyCase("sinkingCylinder2D");
    replaceInFile(dir / "system/generateParticlesDict", "layers 1; firstLayerOffset 0;", "layers 3;");  // a layout dummy particles accept
    writeFile(dir / "constant/boundaryProperties",
              "tank { type dummyParticles; }\ncylinder { type dummyParticles; motion { type freeBody; mass 1; momentOfInertia 1; centreOfMass (0.5 "
              "0.3); } }\n");
    expectContains(failureOf(dir), "a free body takes its loads from a wall-force model");
}

TEST(BadInput, UnknownPeriodicDirection) {
    const auto dir = copyCase("poiseuille2D");
    replaceInFile(dir / "system/generateParticlesDict", "periodic (x);", "periodic (z);");
    expectContains(failureOf(dir),
                   "error: keyword 'periodic' in dictionary 'generateParticlesDict/domain': unknown direction 'z'; valid directions are: x y");
}

TEST(BadInput, SolidBelowWhatTheSpacingResolves) {
    // A triangle with legs of one spacing on the correction's one layer: its three particles,
    // one on each corner, leave the fluid beside two of its faces behind the third's plane.
    const auto triangle = [](double legs) {
        const auto dir = copyCase("damBreak2D");
        setEntry(dir / "system/generateParticlesDict", "spacing", "0.0028575");
        const std::string tip = fmt::format("{:.7g}", 0.02 + legs * 0.0028575);
        replaceInFile(
            dir / "system/generateParticlesDict", "open (yMax); }",
            "open (yMax); }\n    block { type polygon; points ((0.02 0.02) (" + tip + " 0.02) (0.02 " + tip + ")); side right; layers 1; }");
        replaceInFile(dir / "constant/boundaryProperties", "noSlip no; }", "noSlip no; }\nblock { type deficiencyCorrectionBoundaryIntegral; }");
        return dir;
    };
    try {
        sph::generateParticles(triangle(1.0), true);
        ADD_FAILURE() << "a triangle of 1 dx generated";
    } catch (const sph::FatalError& e) {
        expectContains(e.what(),
                       "wall patch 'block' has fluid on both sides: 2 of the 7 fluid particles next to it lie behind its wall particles' "
                       "normals (a solid body this small is below what the spacing resolves");
    }
    EXPECT_NO_THROW(sph::generateParticles(triangle(8.0), true));
}

TEST(BadInput, NegativeOrZeroSpacing) {
    for (const std::string spacing : {"-0.00142875", "0"}) {
        const auto dir = copyCase("damBreak2D");
        replaceInFile(dir / "system/generateParticlesDict", "spacing     0.00142875;", "spacing     " + spacing + ";");
        expectContains(failureOf(dir), "error: keyword 'spacing' in dictionary 'generateParticlesDict': must be greater than zero, found " + spacing);
    }
}

TEST(BadInput, SmoothingLengthSmallerThanSpacing) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/sphSchemes", "hdx 1.3;", "hdx 0.8;");
    expectContains(failureOf(dir),
                   "error: keyword 'hdx' in dictionary 'sphSchemes/kernel': h = hdx dx must not be smaller than the particle spacing; "
                   "found hdx 0.8 (valid: >= 1)");
}

TEST(BadInput, FluidOutsideTheDomain) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/generateParticlesDict", "column  { type box; min (0 0); max ($a 0.1143); }",
                  "column  { type box; min (-0.05715 0); max (0 0.1143); }");
    const std::string message = failureOf(dir);
    expectContains(message, (dir / "system/generateParticlesDict").string() + ":12:13:");
    expectContains(message, "error: fluid region 'column' has a particle at (-0.0564356 0.000714375) outside the domain [(-0.03 -0.03), (0.43 0.2)]");
}

TEST(BadInput, NoFluidParticles) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/generateParticlesDict", "column  { type box; min (0 0); max ($a 0.1143); }",
                  "column  { type circle; centre (0.1 0.1); radius 0.0001; }");
    expectContains(failureOf(dir), "error: fluid region 'column' holds no particle");
}

TEST(BadInput, EmptyFluidStateIsRejectedBySolver) {
    const auto dir = copyCase("damBreak2D");
    sph::generateParticles(dir, true);
    sph::StateHeader header;
    auto fluid = sph::readParticleFile<2>(dir / "0/fluid.vtu", "fluid", header);
    fluid.resize(0);
    sph::writeParticleFile(dir / "0/fluid.vtu", fluid, header);
    expectContains(failureOf(dir, false), "error: '" + (dir / "0/fluid.vtu").string() + "' holds no fluid particles");
}

TEST(BadInput, NonFiniteOrNonPositiveStateValues) {
    const auto dir = copyCase("damBreak2D");
    sph::generateParticles(dir, true);
    sph::StateHeader header;
    const auto original = sph::readParticleFile<2>(dir / "0/fluid.vtu", "fluid", header);
    auto fluid = original;
    fluid[sph::fields::density][7] = std::numeric_limits<double>::quiet_NaN();
    sph::writeParticleFile(dir / "0/fluid.vtu", fluid, header);
    expectContains(failureOf(dir, false), "error: particle file '" + (dir / "0/fluid.vtu").string() + "': particle id " +
                                              std::to_string(fluid.globalId[7]) + " has a non-finite density (a corrupt state file?)");
    fluid = original;
    fluid[sph::fields::mass][3] = -1.0;
    sph::writeParticleFile(dir / "0/fluid.vtu", fluid, header);
    expectContains(failureOf(dir, false), "has mass -1, not positive (a corrupt state file?)");
}

TEST(BadInput, DuplicateIdsCoincidentParticlesAndZeroNormals) {
    // Each was accepted silently on c09449c (a zero normal left its wall particle without a side).
    const auto dir = copyCase("damBreak2D");
    sph::generateParticles(dir, true);
    sph::StateHeader header, wallHeader;
    const auto original = sph::readParticleFile<2>(dir / "0/fluid.vtu", "fluid", header);
    const auto walls = sph::readParticleFile<2>(dir / "0/walls.vtu", "walls", wallHeader);
    auto fluid = original;
    fluid.globalId[5] = fluid.globalId[2];
    sph::writeParticleFile(dir / "0/fluid.vtu", fluid, header);
    expectContains(failureOf(dir, false), fmt::format("'{}': particles 2 and 5 (in file order) have the same id 2", (dir / "0/fluid.vtu").string()));
    fluid = original;
    fluid.position[9] = fluid.position[4];
    sph::writeParticleFile(dir / "0/fluid.vtu", fluid, header);
    expectContains(failureOf(dir, false), "are at the same position (");
    sph::writeParticleFile(dir / "0/fluid.vtu", original, header);
    auto zeroNormal = walls;
    zeroNormal[sph::fields::normal][3] = sph::Vec<2>::Zero();
    sph::writeParticleFile(dir / "0/walls.vtu", zeroNormal, wallHeader);
    expectContains(failureOf(dir, false), "wall particle id 3 has the normal (0 0) of length 0 (valid: a unit vector)");
}

TEST(BadInput, TruncatedStateFile) {
    // A state cut short (copied from a full disk by hand, say) reads as an error, not as fewer particles.
    const auto dir = copyCase("damBreak2D");
    sph::generateParticles(dir, true);
    const auto file = dir / "0/fluid.vtu";
    std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
    expectContains(failureOf(dir, false), "error: particle file '" + file.string() + "': array 'Points' (offset ");
    expectContains(failureOf(dir, false), "bytes that run past the end of the file (a corrupt state file?)");
}

TEST(BadInput, CorruptFreeBodyRestartState) {
    const auto dir = copyCase("sinkingCylinder2D");
    replaceInFile(dir / "system/caseParameters", "dx          0.01;", "dx          0.02;");
    replaceInFile(dir / "system/controlDict", "endTime         0.3;", "endTime         0.02;");
    sph::generateParticles(dir, true);
    sph::runCase(dir);
    replaceInFile(dir / "system/controlDict", "endTime         0.02;", "endTime         0.04;");
    sph::StateHeader header;
    const auto fluid = sph::readParticleFile<2>(dir / "0.02/fluid.vtu", "fluid", header);
    ASSERT_EQ(header.restart.count("motion:cylinder"), 1u);
    header.restart["motion:cylinder"].resize(3);
    sph::writeParticleFile(dir / "0.02/fluid.vtu", fluid, header);
    expectContains(failureOf(dir, false), "error: '" + (dir / "0.02/fluid.vtu").string() +
                                              "': the saved free-body state has 3 values, expected 15 finite values (a corrupt state file?)");
}

TEST(BadInput, StartTimeThatWasNotWritten) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/controlDict", "startFrom       latestTime;", "startFrom       startTime;\nstartTime       0.5;");
    sph::generateParticles(dir, true);
    expectContains(failureOf(dir, false), "no time directory 0.5 with a fluid.vtu or fluid.pvtu; written times are: 0");
}

TEST(BadInput, EndTimeNotAfterTheStartTime) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/controlDict", "endTime         0.2;", "endTime         0;");
    expectContains(failureOf(dir), "error: keyword 'endTime' in dictionary 'controlDict': must be later than the start time 0, found 0");
}

TEST(BadInput, MissingStateTellsToGenerateParticles) {
    const auto dir = copyCase("damBreak2D");
    expectContains(failureOf(dir, false), "has no time directory with a fluid.vtu or fluid.pvtu state; run generateParticles first to write 0/");
}

TEST(BadInput, MissingKeyword) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/controlDict", "endTime ", "endTme ");
    expectContains(failureOf(dir), "error: keyword 'endTime' is missing from dictionary 'controlDict' (is 'endTme' at " +
                                       (dir / "system/controlDict").string() + ":");
}

TEST(BadInput, MisspeltOptionalKeywordIsNotIgnored) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/timeIntegration", "courant", "courrant");
    const std::string message = failureOf(dir);
    expectContains(message, "keyword(s) not recognised by the selected models");
    expectContains(message, (dir / "system/timeIntegration").string() + ":2:1: 'courrant' in dictionary 'timeIntegration' (did you mean 'courant'?)");
}

TEST(BadInput, WrongTypeSaysWhatWasFound) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/controlDict", "writeInterval   0.01;", "writeInterval   often;");
    expectContains(failureOf(dir), "error: keyword 'writeInterval' in dictionary 'controlDict': expected a number, found word 'often'");
}

TEST(BadInput, PatchThatIsNotInTheState) {
    const auto dir = copyCase("damBreak2D");
    writeFile(dir / "constant/boundaryProperties", "tank { type dummyParticles; }\nlid { type dynamicBoundary; }\n");
    expectContains(failureOf(dir), "error: patch 'lid' in constant/boundaryProperties is not a wall patch of the case; its patches are: tank");
}

TEST(BadInput, DiffusionWithSummationDensity) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/sphSchemes", "type continuity;", "type summation;");
    expectContains(failureOf(dir), "density diffusion acts on the continuity equation; with summation density select 'none' or leave it out");
}

TEST(BadInput, DiffusionKeywordIsNeededWithContinuityDensityOnly) {
    const auto dir = coarseDamBreak("0.002");
    replaceInFile(dir / "system/sphSchemes", "densityDiffusion    { type fourtakas; delta 0.1; }", "");
    expectContains(failureOf(dir, false), "keyword 'densityDiffusion' is missing from dictionary 'sphSchemes'");
    replaceInFile(dir / "system/sphSchemes", "type continuity;", "type summation;");
    EXPECT_EQ(failureOf(dir, false), "");  // summation density has nothing to diffuse
}

TEST(BadInput, SpeedOfSoundMissing) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "constant/fluidProperties", "c0FromHeight", "c0Height");
    expectContains(failureOf(dir),
                   "error: dictionary 'fluidProperties/equationOfState' needs the speed of sound: 'c0 <value>;' or "
                   "'c0FromHeight { coefficient 10; height <H>; }'");
}

TEST(BadInput, BoxUnderHalfASpacing) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/generateParticlesDict", "max (0.40005 0.17145)", "max (0.0005 0.17145)");
    expectContains(failureOf(dir),
                   "error: keyword 'max' in dictionary 'generateParticlesDict/boundaries/tank': the extent 0.0005 (from 0 to 0.0005) must be "
                   "at least half a spacing dx = 0.00142875");
}

TEST(BadInput, ExistingInitialStateIsNotOverwrittenByDefault) {
    const auto dir = copyCase("damBreak2D");
    sph::generateParticles(dir, false);
    try {
        sph::generateParticles(dir, false);
        FAIL() << "0/ was overwritten";
    } catch (const sph::FatalError& e) {
        expectContains(e.what(), "exists; remove it (./Allclean) or pass -overwrite");
    }
}

TEST(BadInput, UnknownButcherTableListsSundialsTables) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/timeIntegration", "type symplectic;", "type arkodeERK; table ARKODE_RK4;");
    const std::string message = failureOf(dir);
    expectContains(message, "error: keyword 'table' in dictionary 'timeIntegration/integrator': unknown table 'ARKODE_RK4'; valid names are:");
    expectContains(message, "    ARKODE_DORMAND_PRINCE_7_4_5\n");
}

TEST(BadInput, UnknownAdaptivityController) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/timeIntegration", "type symplectic;", "type arkodeERK; adaptive yes; controller PD;");
    expectContains(failureOf(dir), "unknown adaptivity controller 'PD'; valid controller names are:\n    PID\n    PI\n    I\n    explicitGustafsson");
}

TEST(BadInput, VelocityBlockJacobianNeedsLaminarViscosity) {
    const auto dir = copyCase("damBreak2D");  // artificial viscosity
    replaceInFile(dir / "system/timeIntegration", "type symplectic;", "type arkodeIMEX; jacobianTimesVector velocityBlock;");
    expectContains(failureOf(dir), "velocityBlock is exact only for a viscosity linear in velocity (laminar)");
}

TEST(BadInput, ImplicitViscosityBesideTheCorrectionsNoSlipWall) {
    const auto dir = copyCase("poiseuille2D");  // laminar viscosity: the correction's walls default to no-slip
    replaceInFile(dir / "system/generateParticlesDict", "layers 3; ", "");
    replaceInFile(dir / "system/generateParticlesDict", "layers 3; ", "");
    writeFile(dir / "constant/boundaryProperties",
              "floor { type deficiencyCorrectionBoundaryIntegral; }\nceiling { type deficiencyCorrectionBoundaryIntegral; }\n");
    replaceInFile(dir / "system/timeIntegration", "type symplectic;", "type arkodeIMEX;");
    expectContains(failureOf(dir), "arkodeIMEX takes the fluid's viscosity implicitly, but wall patch 'floor' adds its laminar stress");
}

TEST(BadInput, NoSlipOnTheCorrectionNeedsLaminarViscosity) {
    const auto dir = copyCase("damBreak2D");  // artificial viscosity
    writeFile(dir / "constant/boundaryProperties", "tank { type deficiencyCorrectionBoundaryIntegral; noSlip yes; }\n");
    expectContains(failureOf(dir),
                   "keyword 'noSlip' in dictionary 'boundaryProperties/tank': a no-slip wall on the correction needs viscosity laminar");
}

TEST(BadInput, FreeBodyWithAnIntegratorThatCannotAdvanceIt) {
    const auto dir = copyCase("sinkingCylinder2D");
    replaceInFile(dir / "system/timeIntegration", "type symplectic;", "type verlet;");
    expectContains(failureOf(dir), "patch 'cylinder' is a free body, which only the symplectic integrator advances; found verlet");
}

TEST(BadInput, EulerEveryMustBePositive) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/timeIntegration", "type symplectic;", "type verlet; eulerEvery 0;");
    expectContains(failureOf(dir), "keyword 'eulerEvery' in dictionary 'timeIntegration/integrator': must be at least 1, found 0");
}

TEST(BadInput, AnalyticInitialPressureNeedsASolutionWithPressure) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/generateParticlesDict", "initialPressure hydrostatic;", "initialPressure analytic;");
    expectContains(failureOf(dir),
                   "keyword 'initialPressure' in dictionary 'generateParticlesDict': 'analytic' needs fluid region 'column' to take "
                   "its velocity from a solution with a pressure field");
    const auto couette = copyCase("couette2D", "couette");
    replaceInFile(couette / "system/generateParticlesDict", "water   { type box; min (0 0); max (5e-4 1e-3); }",
                  "water   { type box; min (0 0); max (5e-4 1e-3); velocity { type couette; V0 1; L 1e-3; nu 1e-6; } }");
    replaceInFile(couette / "system/generateParticlesDict", "dimension   2;", "dimension   2;\ninitialPressure analytic;");
    expectContains(failureOf(couette), "'analytic' needs fluid region 'water' to take its velocity from a solution with a pressure field");
}

TEST(BadInput, UnknownAnalyticSolutionListsTheValidNames) {
    const auto dir = copyCase("taylorGreen2D");
    replaceInFile(dir / "system/controlDict", "solution        { type taylorGreen;", "solution        { type taylorGren;");
    const std::string message = failureOf(dir);
    expectContains(message, (dir / "system/controlDict").string() + ":");
    expectContains(message,
                   "unknown analytic solution 'taylorGren'; valid analytic solution names are:\n    couette\n    ellipticalDrop\n    hydrostatic");
}

TEST(BadInput, ProbeOutsideTheDomainStopsBeforeTheFirstStep) {
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/controlDict", "functions\n{", "functions\n{\n    p { type probes; fields (p); points ((0.1 0.01) (0.5 0.01)); }");
    expectContains(failureOf(dir),
                   "keyword 'points' in dictionary 'controlDict/functions/p': probe 1 at (0.5 0.01) lies outside the domain "
                   "[(-0.03 -0.03), (0.43 0.2)]");
    EXPECT_FALSE(std::filesystem::exists(dir / "0.01")) << "a step was taken";
}

TEST(BadInput, ReferenceWithAMissingColumnStopsBeforeTheFirstStep) {
    // (Rows that step back in time are sorted with a note: ReferenceSeries.RowsThatStepBackAreSortedWithANote.)
    const auto dir = copyCase("damBreak2D");
    writeFile(dir / "martinMoyce1952Front.csv", "T,X\n0.41,1.11\n0.84,1.22\n");
    expectContains(failureOf(dir), "has no column 'Z'; its columns are: T, X");
}

TEST(BadInput, RunawaySizesAreRefusedBeforeAllocation) {
    // On c09449c: spacing 1e-10 overflowed an int and generated 1 particle; smaller spacings,
    // 1e8 layers and 2e9 sample points ran until the memory ran out.
    auto dir = copyCase("damBreak2D", "tiny");
    setEntry(dir / "system/generateParticlesDict", "spacing", "1e-10");
    expectContains(failureOf(dir),
                   "keyword 'spacing' in dictionary 'generateParticlesDict': the domain is 4.6e+09 spacings of 1e-10 across in direction 0 "
                   "(at most 2147483647): is the spacing a slip?");
    dir = copyCase("damBreak2D", "small");
    setEntry(dir / "system/generateParticlesDict", "spacing", "2e-6");
    const std::string memory = failureOf(dir);
    expectContains(memory, "spacing 2e-06 over the domain (2.65e+10 lattice points) would need 394 GiB of memory; this machine has");
    dir = copyCase("damBreak2D", "layers");
    replaceInFile(dir / "system/generateParticlesDict", "layers 3;", "layers 100000000;");
    expectContains(failureOf(dir), "keyword 'layers' in dictionary 'generateParticlesDict/boundaries/tank': must be from 1 to 1000, found 100000000");
    dir = copyCase("hydrostaticTank2D", "points");
    setEntry(dir / "system/controlDict", "points", "2000000000");
    expectContains(failureOf(dir), "keyword 'points' in dictionary 'controlDict/functions/");
    expectContains(failureOf(dir), "must be from 2 to 10000000, found 2000000000");
}

TEST(BadInput, CourantNumberAboveOne) {
    // Accepted silently on c09449c (and blew up some steps later).
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/timeIntegration", "courant     0.2;", "courant     10;");
    expectContains(failureOf(dir), "keyword 'courant' in dictionary 'timeIntegration': must not exceed 1");
}

TEST(BadInput, WallPatchListedTwice) {
    // Twice the wall particles on c09449c, each pair at one place.
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/generateParticlesDict", "open (yMax); }",
                  "open (yMax); }\n    again { type boxWalls; min (0 0); max (0.40005 0.17145); layers 3; open (yMax); }");
    expectContains(failureOf(dir), "wall patch 'again' lays 1578 of its 1578 particles on those of patch 'tank' (the same patch listed twice?)");
}

TEST(BadInput, FluidOutsideTheTankIsAWarning) {
    // Meant at times (walls as obstacles in an open domain), so a warning that generateParticles prints.
    const auto dir = copyCase("damBreak2D");
    replaceInFile(dir / "system/generateParticlesDict", "column  { type box; min (0 0); max ($a 0.1143); }",
                  "column  { type box; min (0 0); max ($a 0.1143); }\n    spill { type box; min (0.41 0); max (0.4242875 0.0142875); }");
    const sph::GenerationSummary summary = sph::generateParticles(dir, true);
    ASSERT_EQ(summary.warnings.size(), 1u);
    expectContains(summary.warnings[0], "fluid region 'spill' has 100 of its 100 particles outside the box around the wall particles");
    EXPECT_TRUE(sph::generateParticles(copyCase("damBreak2D", "inside"), true).warnings.empty());
}

TEST(BadInput, LaterTimesAreNotOverwrittenWithoutAFlag) {
    // startFrom startTime overwrote the later times without a word on c09449c.
    const auto dir = coarseDamBreak("0.02");
    sph::runCase(dir);
    ASSERT_TRUE(std::filesystem::exists(dir / "0.02/fluid.vtu"));
    std::ofstream(dir / "system/controlDict", std::ios::app) << "startFrom startTime;\nstartTime 0.01;\n";
    expectContains(failureOf(dir, false),
                   "the run starts at t = 0.01, but the case has later times (written by an earlier run): 0.02; the run would "
                   "overwrite them. Start from latestTime, remove them, or run wcsph -overwrite to have them removed");
    EXPECT_TRUE(std::filesystem::exists(dir / "0.02/fluid.vtu"));
    sph::runCase(dir, sph::RunMode::TimeLoop, true);
    EXPECT_TRUE(std::filesystem::exists(dir / "0.02/fluid.vtu"));  // written again by this run
    // generateParticles -overwrite replaces 0/ and removes what the solver wrote from the old 0/.
    sph::generateParticles(dir, true);
    EXPECT_FALSE(std::filesystem::exists(dir / "0.01"));
    EXPECT_FALSE(std::filesystem::exists(dir / "0.02"));
    EXPECT_TRUE(std::filesystem::exists(dir / "0/fluid.vtu"));
}

TEST(BadInput, EmptyTimeDirectoryIsAWarning) {
    // Skipped without a word on c09449c: a user who copied a time without its files saw the run start elsewhere.
    const auto dir = coarseDamBreak("0.01");
    std::filesystem::create_directories(dir / "0.5");
    ::testing::internal::CaptureStdout();
    sph::runCase(dir);
    const std::string log = ::testing::internal::GetCapturedStdout();
    expectContains(log, "warning: skipping the time directory " + (dir / "0.5").string() + ": it holds no fluid.vtu or fluid.pvtu");
}
