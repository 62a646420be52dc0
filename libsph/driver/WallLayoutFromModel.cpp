#include "driver/WallLayoutFromModel.hpp"

#include "boundaryModels/BoundaryModel.hpp"
#include "core/FatalError.hpp"
#include "driver/CaseDirectory.hpp"
#include "io/SelectByType.hpp"
#include "kernels/Kernel.hpp"
#include "viscosity/ArtificialViscosityMonaghan1992.hpp"
#include "viscosity/LaminarViscosityMorris1997.hpp"

#include <fmt/format.h>

#include <variant>

namespace sph {

template <int D>
WallLayoutFromModel<D>::WallLayoutFromModel(std::filesystem::path caseDirectory, double dx, const FluidProperties<D>& properties)
    : caseDirectory_(std::move(caseDirectory)), dx_(dx), properties_(properties) {}

template <int D>
const Dictionary* WallLayoutFromModel<D>::modelOf(const std::string& name) {
    if (!boundaryDict_) {
        if (!std::filesystem::exists(caseDirectory_ / "constant/boundaryProperties")) return nullptr;
        boundaryDict_ = readCaseDictionary(caseDirectory_, "constant/boundaryProperties");
        const Dictionary schemes = readCaseDictionary(caseDirectory_, "system/sphSchemes");
        const Dictionary& kernelDict = schemes.subDict("kernel");
        h_ = kernelDict.getPositive("hdx") * dx_;
        const Kernel<D> kernel = selectByType(makeKernelRegistry<D>(), kernelDict, h_);
        support_ = std::visit([](const auto& k) { return k.supportRadius(); }, kernel);
        if (const Dictionary* viscosity = schemes.findSubDict("viscosity")) viscosity_ = viscosity->getOrDefault<std::string>("type", "");
    }
    return boundaryDict_->findSubDict(name);
}

template <int D>
WallLayout WallLayoutFromModel<D>::layoutOf(const Dictionary& modelDict, std::string& note) const {
    ModelContext context = modelContext(properties_, dx_, h_);
    context.artificialViscosity = viscosity_ == ArtificialViscosityMonaghan1992::name;
    context.laminarViscosity = viscosity_ == LaminarViscosityMorris1997::name;
    const auto model = selectByType(makeBoundaryModelRegistry<D>(), modelDict, modelDict, context);
    const std::string type = modelDict.get<std::string>("type");
    if (!model->actsThroughWallParticles()) {
        note = fmt::format("1 layer on the wall surface, for the wall-force model {}", type);
        return {1, 0.0};
    }
    const int layers = model->layersToGenerate(support_, dx_);
    note = fmt::format("{} layers from dx/2 behind the wall, for {} with a kernel support of {:g} dx", layers, type, support_ / dx_);
    return {layers, 0.5};
}

template <int D>
WallLayout WallLayoutFromModel<D>::operator()(const std::string& name, const Dictionary& patch, std::string& note) {
    const Dictionary* modelDict = modelOf(name);
    if (!modelDict)
        throw FatalError(
            patch.where(),
            fmt::format("wall patch '{}' names no layers, so they are taken from its wall model, but {}; "
                        "give the patch layers (and firstLayerOffset), or select its model in "
                        "constant/boundaryProperties: {} {{ type dummyParticles; }}",
                        name, boundaryDict_ ? "constant/boundaryProperties has no entry for it" : "the case has no constant/boundaryProperties",
                        name));
    return layoutOf(*modelDict, note);
}

template <int D>
std::optional<double> WallLayoutFromModel<D>::offsetOf(const std::string& name, std::string& note) {
    const Dictionary* modelDict = modelOf(name);
    if (!modelDict) return std::nullopt;
    std::string why;
    const WallLayout layout = layoutOf(*modelDict, why);
    if (layout.firstLayerOffset == 0.0)
        note =
            fmt::format("firstLayerOffset 0, the first layer on the wall surface, for the wall-force model {}", modelDict->get<std::string>("type"));
    return layout.firstLayerOffset;
}

template class WallLayoutFromModel<1>;
template class WallLayoutFromModel<2>;
template class WallLayoutFromModel<3>;

}  // namespace sph
