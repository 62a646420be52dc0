#include "parallel/RcbPartition.hpp"

#include <zoltan.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace sph::parallel {

namespace {

template <int D>
struct LocalPoints {
    std::span<const Vec<D>> points;
    std::span<const double> weights;
    ZOLTAN_ID_TYPE firstGlobalId;
};

template <int D>
int pointCount(void* data, int* error) {
    *error = ZOLTAN_OK;
    return static_cast<int>(static_cast<LocalPoints<D>*>(data)->points.size());
}

template <int D>
void listPoints(void* data, int, int, ZOLTAN_ID_PTR globalIds, ZOLTAN_ID_PTR localIds, int weightsPerPoint, float* weights, int* error) {
    const auto& local = *static_cast<LocalPoints<D>*>(data);
    for (std::size_t i = 0; i < local.points.size(); ++i) {
        globalIds[i] = local.firstGlobalId + i;
        localIds[i] = i;
        if (weightsPerPoint == 1) weights[i] = static_cast<float>(local.weights[i]);
    }
    *error = ZOLTAN_OK;
}

template <int D>
int dimension(void*, int* error) {
    *error = ZOLTAN_OK;
    return D;
}

template <int D>
void coordinates(void* data, int, int, int count, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR localIds, int, double* xyz, int* error) {
    const auto& local = *static_cast<LocalPoints<D>*>(data);
    for (int i = 0; i < count; ++i)
        for (int d = 0; d < D; ++d) xyz[i * D + d] = local.points[localIds[i]][d];
    *error = ZOLTAN_OK;
}

void check(int status, const char* call) {
    if (status != ZOLTAN_OK && status != ZOLTAN_WARN) throw std::runtime_error(std::string("Zoltan: ") + call + " failed");
}

struct ZoltanDeleter {
    void operator()(Zoltan_Struct* zoltan) const { Zoltan_Destroy(&zoltan); }
};

}  // namespace

template <int D>
DomainBoxes<D> partitionByRcb(const Communicator& ranks, std::span<const Vec<D>> points, std::span<const double> weights, const Vec<D>& lower,
                              const Vec<D>& upper, const Vec<D>& period) {
    if (weights.size() != points.size()) throw std::logic_error("partitionByRcb needs one weight per point");
    constexpr double infinity = std::numeric_limits<double>::infinity();
    // Every face at infinity, but a periodic direction's, at the domain's faces.
    RankBox<D> everywhere{Vec<D>::Constant(-infinity), Vec<D>::Constant(infinity)};
    for (int d = 0; d < D; ++d)
        if (period[d] > 0.0) everywhere.lower[d] = lower[d], everywhere.upper[d] = upper[d];
    if (ranks.size() == 1) return DomainBoxes<D>({everywhere}, period);

    static const bool initialised = [] {
        float version = 0.0f;
        return Zoltan_Initialize(0, nullptr, &version) == ZOLTAN_OK;
    }();
    if (!initialised) throw std::runtime_error("Zoltan: Zoltan_Initialize failed");

    std::int64_t before = 0;
    const auto count = static_cast<std::int64_t>(points.size());
    MPI_Exscan(&count, &before, 1, MPI_INT64_T, MPI_SUM, ranks.handle());
    LocalPoints<D> local{points, weights, static_cast<ZOLTAN_ID_TYPE>(ranks.rank() == 0 ? 0 : before)};

    std::unique_ptr<Zoltan_Struct, ZoltanDeleter> zoltan(Zoltan_Create(ranks.handle()));
    if (!zoltan) throw std::runtime_error("Zoltan: Zoltan_Create failed");
    for (const auto& [name, value] : {std::pair{"DEBUG_LEVEL", "0"},
                                      {"LB_METHOD", "RCB"},
                                      {"NUM_GID_ENTRIES", "1"},
                                      {"NUM_LID_ENTRIES", "1"},
                                      {"OBJ_WEIGHT_DIM", "1"},
                                      {"RETURN_LISTS", "NONE"},
                                      {"KEEP_CUTS", "1"},
                                      {"RCB_RECTILINEAR_BLOCKS", "1"},
                                      {"AVERAGE_CUTS", "1"}})
        check(Zoltan_Set_Param(zoltan.get(), name, value), "Zoltan_Set_Param");
    Zoltan_Set_Num_Obj_Fn(zoltan.get(), pointCount<D>, &local);
    Zoltan_Set_Obj_List_Fn(zoltan.get(), listPoints<D>, &local);
    Zoltan_Set_Num_Geom_Fn(zoltan.get(), dimension<D>, &local);
    Zoltan_Set_Geom_Multi_Fn(zoltan.get(), coordinates<D>, &local);

    int changes = 0, gidEntries = 0, lidEntries = 0, imports = 0, exports = 0;
    ZOLTAN_ID_PTR importGlobal = nullptr, importLocal = nullptr, exportGlobal = nullptr, exportLocal = nullptr;
    int *importRanks = nullptr, *importParts = nullptr, *exportRanks = nullptr, *exportParts = nullptr;
    check(Zoltan_LB_Partition(zoltan.get(), &changes, &gidEntries, &lidEntries, &imports, &importGlobal, &importLocal, &importRanks, &importParts,
                              &exports, &exportGlobal, &exportLocal, &exportRanks, &exportParts),
          "Zoltan_LB_Partition");
    Zoltan_LB_Free_Part(&importGlobal, &importLocal, &importRanks, &importParts);
    Zoltan_LB_Free_Part(&exportGlobal, &exportLocal, &exportRanks, &exportParts);

    std::vector<RankBox<D>> boxes(static_cast<std::size_t>(ranks.size()), everywhere);
    for (int part = 0; part < ranks.size(); ++part) {
        int dims = 0;
        std::array<double, 3> low{}, high{};
        check(Zoltan_RCB_Box(zoltan.get(), part, &dims, &low[0], &low[1], &low[2], &high[0], &high[1], &high[2]), "Zoltan_RCB_Box");
        RankBox<D>& box = boxes[static_cast<std::size_t>(part)];
        // Zoltan marks an open side with the largest double: that side stays where `everywhere` has it.
        for (int d = 0; d < D; ++d) {
            if (low[d] > -std::numeric_limits<double>::max()) box.lower[d] = low[d];
            if (high[d] < std::numeric_limits<double>::max()) box.upper[d] = high[d];
        }
    }
    return DomainBoxes<D>(std::move(boxes), period);
}

double loadImbalance(const Communicator& ranks, double localWeight) {
    double total = 0.0;
    MPI_Allreduce(&localWeight, &total, 1, MPI_DOUBLE, MPI_SUM, ranks.handle());
    const double largest = ranks.maxOverRanks(localWeight);
    return total > 0.0 ? largest * ranks.size() / total : 1.0;
}

template DomainBoxes<1> partitionByRcb(const Communicator&, std::span<const Vec<1>>, std::span<const double>, const Vec<1>&, const Vec<1>&,
                                       const Vec<1>&);
template DomainBoxes<2> partitionByRcb(const Communicator&, std::span<const Vec<2>>, std::span<const double>, const Vec<2>&, const Vec<2>&,
                                       const Vec<2>&);
template DomainBoxes<3> partitionByRcb(const Communicator&, std::span<const Vec<3>>, std::span<const double>, const Vec<3>&, const Vec<3>&,
                                       const Vec<3>&);

}  // namespace sph::parallel
