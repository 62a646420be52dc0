#include "core/Registry.hpp"
#include "driver/ModelCatalogue.hpp"
#include "kernels/Kernel.hpp"
#include "motion/PatchMotion.hpp"

#include <gtest/gtest.h>

using sph::FatalError;
using sph::Registry;
using sph::SourceLocation;

namespace {

SourceLocation at(int line, int column) { return {std::make_shared<const std::string>("system/sphSchemes"), line, column}; }

}  // namespace

TEST(Registry, CreatesTheNamedModel) {
    Registry<int, int> registry("number");
    registry.add("double", {"twice", "", {}}, [](int x) { return 2 * x; });
    registry.add("square", {"squared", "", {}}, [](int x) { return x * x; });
    EXPECT_EQ(registry.create("double", at(1, 1), 7), 14);
    EXPECT_EQ(registry.create("square", at(1, 1), 7), 49);
    EXPECT_EQ(registry.names(), (std::vector<std::string>{"double", "square"}));
}

TEST(Registry, UnknownNameListsTheSortedValidNamesWithItsLocation) {
    const auto kernels = sph::makeKernelRegistry<2>();
    try {
        kernels.create("gaussian", at(3, 17), 1.0);
        FAIL() << "no error for an unknown kernel";
    } catch (const FatalError& e) {
        EXPECT_STREQ(e.what(),
                     "system/sphSchemes:3:17: error: unknown kernel 'gaussian'; valid kernel names are:\n"
                     "    cubicSpline\n    quinticSpline\n    wendlandC2\n    wendlandC4\n    wendlandC6");
    }
}

TEST(Registry, AMisspeltNameSaysWhatWasMeant) {
    const auto kernels = sph::makeKernelRegistry<2>();
    try {
        kernels.create("wendlandc4", at(1, 28), 1.0);
        FAIL() << "no error for a misspelt kernel";
    } catch (const FatalError& e) {
        EXPECT_STREQ(e.what(),
                     "system/sphSchemes:1:28: error: unknown kernel 'wendlandc4'; valid kernel names are:\n"
                     "    cubicSpline\n    quinticSpline\n    wendlandC2\n    wendlandC4\n    wendlandC6\n(did you mean 'wendlandC4'?)");
    }
    // Nothing near: no guess (the unknown name above, gaussian, gets none either).
    EXPECT_EQ(kernels.unknownMessage("sph").find("did you mean"), std::string::npos);
}

TEST(Registry, DuplicateRegistrationIsAnError) {
    Registry<int> registry("viscosity");
    registry.add("artificial", {}, [] { return 1; });
    EXPECT_THROW(registry.add("artificial", {}, [] { return 2; }), FatalError);
    try {
        registry.add("artificial", {}, [] { return 2; });
    } catch (const FatalError& e) {
        EXPECT_STREQ(e.what(), "error: viscosity 'artificial' is registered twice");
    }
}

TEST(Registry, SelectedKernelHasTheRequestedSmoothingLength) {
    const auto kernel = sph::makeKernelRegistry<3>().create("wendlandC4", at(1, 1), 0.25);
    ASSERT_TRUE(std::holds_alternative<sph::WendlandC4<3>>(kernel));
    EXPECT_DOUBLE_EQ(std::get<sph::WendlandC4<3>>(kernel).h, 0.25);
}

TEST(ModelCatalogue, ListsEveryFamilyWithTheMotionsAndTheirKeywords) {
    const std::string catalogue = sph::modelCatalogue();
    for (const char* family : {"kernel (", "viscosity (", "densityDiffusion (", "equationOfState (", "boundary model (", "motion (",
                               "time integrator (", "function object (", "analytic solution ("})
        EXPECT_NE(catalogue.find(family), std::string::npos) << family;
    for (const std::string& name : sph::makePatchMotionRegistry<2>().names())
        EXPECT_NE(catalogue.find("    " + name + " "), std::string::npos) << name;
    EXPECT_NE(catalogue.find("rampTime"), std::string::npos);
}

TEST(ModelCatalogue, ListsOneFamilyByNameAndNamesTheValidOnes) {
    const std::string motions = sph::modelCatalogue("motion");
    EXPECT_EQ(motions.find("motion ("), 0u);
    EXPECT_EQ(motions.find("kernel ("), std::string::npos);
    EXPECT_NE(sph::modelCatalogue("boundary").find("deficiencyCorrectionBoundaryIntegral"), std::string::npos);
    // The generator's shapes, with their keywords.
    EXPECT_NE(sph::modelCatalogue("wallPatch").find("polyline"), std::string::npos);
    EXPECT_NE(sph::modelCatalogue("wallPatch").find("firstLayerOffset"), std::string::npos);
    EXPECT_NE(sph::modelCatalogue("fluidRegion").find("slice"), std::string::npos);
    // Every family alone, and the whole catalogue is their sum.
    std::string all;
    for (const char* family : {"kernel", "density", "viscosity", "densityDiffusion", "particleShifting", "equationOfState", "boundary", "motion",
                               "integrator", "functionObject", "analytic", "fluidRegion", "wallPatch"})
        all += sph::modelCatalogue(family);
    EXPECT_EQ(all, sph::modelCatalogue());
    try {
        sph::modelCatalogue("kernels");
        ADD_FAILURE() << "no error for an unknown family";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()),
                  "unknown model family 'kernels'; valid: kernel density viscosity densityDiffusion particleShifting "
                  "equationOfState boundary motion integrator functionObject analytic fluidRegion wallPatch");
    }
}
