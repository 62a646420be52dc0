#include "driver/WallLayoutFromModel.hpp"

#include "boundaryModels/BoundaryModel.hpp"
#include "core/FatalError.hpp"
#include "driver/CaseDirectory.hpp"
#include "io/SelectByType.hpp"
#include "kernels/Kernel.hpp"

#include <fmt/format.h>

#include <variant>

namespace sph {

template <int D>
WallLayoutFromModel<D>::WallLayoutFromModel(std::filesystem::path caseDirectory, double dx, const FluidProperties<D>& properties)
    : caseDirectory_(std::move(caseDirectory)), dx_(dx), properties_(properties) {}

template <int D>
WallLayout WallLayoutFromModel<D>::operator()(const std::string& name, const Dictionary& patch, std::string& note) {
    const auto noModel = [&](const std::string& why) {
        return FatalError(patch.where(), fmt::format("wall patch '{}' names no layers, so they are taken from its wall model, but {}; "
                                                     "give the patch layers (and firstLayerOffset), or select its model in "
                                                     "constant/boundaryProperties: {} {{ type dummyParticles; }}",
                                                     name, why, name));
    };
    if (!boundaryDict_) {
        if (!std::filesystem::exists(caseDirectory_ / "constant/boundaryProperties")) throw noModel("the case has no constant/boundaryProperties");
        boundaryDict_ = readCaseDictionary(caseDirectory_, "constant/boundaryProperties");
        const Dictionary schemes = readCaseDictionary(caseDirectory_, "system/sphSchemes");
        const Dictionary& kernelDict = schemes.subDict("kernel");
        h_ = kernelDict.getPositive("hdx") * dx_;
        const Kernel<D> kernel = selectByType(makeKernelRegistry<D>(), kernelDict, h_);
        support_ = std::visit([](const auto& k) { return k.supportRadius(); }, kernel);
    }
    const Dictionary* modelDict = boundaryDict_->findSubDict(name);
    if (!modelDict) throw noModel("constant/boundaryProperties has no entry for it");
    const auto model = selectByType(makeBoundaryModelRegistry<D>(), *modelDict, *modelDict, modelContext(properties_, dx_, h_));
    const std::string type = modelDict->get<std::string>("type");
    if (!model->actsThroughWallParticles()) {
        note = fmt::format("1 layer on the wall surface, for the wall-force model {}", type);
        return {1, 0.0};
    }
    const int layers = model->layersToGenerate(support_, dx_);
    note = fmt::format("{} layers from dx/2 behind the wall, for {} with a kernel support of {:g} dx", layers, type, support_ / dx_);
    return {layers, 0.5};
}

template class WallLayoutFromModel<1>;
template class WallLayoutFromModel<2>;
template class WallLayoutFromModel<3>;

}  // namespace sph
