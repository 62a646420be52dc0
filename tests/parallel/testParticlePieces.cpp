// A state in pieces: written by some ranks, read back by as many, fewer or more, every particle
// with every field and the header, and its place in the order a serial run reads the pieces in;
// the .pvtu opens in VTK's parallel reader as one data set; a missing piece stops every rank with
// its name. Two particles of one id, or at one place, on different ranks stop every rank.
#include "core/FatalError.hpp"
#include "io/ParticleState.hpp"
#include "parallel/ParticleMigration.hpp"
#include "parallel/ParticlePieces.hpp"
#include "parallel/ShareOfCase.hpp"
#include "parallel/TestLattice.hpp"

#include <gtest/gtest.h>

#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>

#include <fmt/format.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>

namespace sph::parallel {
namespace {

using namespace test;

// A directory all ranks share, fresh for each test.
std::filesystem::path sharedDirectory(const Communicator& ranks, const std::string& name) {
    const std::filesystem::path directory = std::filesystem::path(SPHKIT_TEST_WORK_DIR) / ("pieces" + std::to_string(ranks.size())) / name;
    if (ranks.rank() == 0) {
        std::filesystem::remove_all(directory);
        std::filesystem::create_directories(directory);
    }
    MPI_Barrier(ranks.handle());
    return directory;
}

// The point arrays an XML file declares, as "type name components", in its order.
std::vector<std::string> declaredPointArrays(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string text(4096, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    const std::size_t begin = text.find("PointData>"), end = text.find("PointData>", begin + 1);
    const std::string pointData = text.substr(begin, end - begin);
    static const std::regex array(R"re(DataArray type="(\w+)" Name="(\w+)"( NumberOfComponents="(\d)")?)re");
    std::vector<std::string> declared;
    for (auto m = std::sregex_iterator(pointData.begin(), pointData.end(), array); m != std::sregex_iterator(); ++m)
        declared.push_back((*m)[1].str() + " " + (*m)[2].str() + " " + ((*m)[4].matched ? (*m)[4].str() : "1"));
    return declared;
}

StateHeader headerAt(double time, long step) {
    StateHeader header;
    header.time = time;
    header.step = step;
    header.spacing = 0.01;
    header.domainMin = {0.0, 0.0};
    header.domainMax = {0.2, 0.2};
    return header;
}

// The lattice partitioned among the first `writers` ranks and written by them in pieces.
void writeOnFirstRanks(const Communicator& world, int writers, const std::filesystem::path& directory) {
    MPI_Comm sub = MPI_COMM_NULL;
    MPI_Comm_split(world.handle(), world.rank() < writers ? 0 : MPI_UNDEFINED, world.rank(), &sub);
    if (sub == MPI_COMM_NULL) return;
    {
        const Communicator ranks(sub);
        ParticleSet<2> set = latticeOnRankZero<2>(ranks, 12, 0.01, 0.2);
        migrateParticles(ranks, set, partitionSet(ranks, set, 0.12, Vec<2>::Zero()));
        writeParticlePieces(ranks, directory, "fluid", set, headerAt(0.25, 40));
    }
    MPI_Comm_free(&sub);
}

TEST(ParticlePieces, AStateWrittenOnSomeRanksIsReadBackOnAnyNumberWhole) {
    const Communicator world;
    // Written by as many ranks, by one fewer, and by one (read back by more).
    for (const int writers : {world.size(), std::max(1, world.size() - 1), 1}) {
        const std::filesystem::path directory = sharedDirectory(world, "written" + std::to_string(writers));
        writeOnFirstRanks(world, writers, directory);
        MPI_Barrier(world.handle());
        StateHeader header;
        ParticleSet<2> set = readParticlePieces<2>(world, directory / "fluid.pvtu", "fluid", header);
        const std::map<std::int64_t, Vec<2>> all = gatherOwned(world, set);
        EXPECT_EQ(all.size(), 144u) << writers << " writers";
        EXPECT_TRUE(all.empty() || (all.begin()->first == 0 && all.rbegin()->first == 143));
        EXPECT_EQ(wrongFields(set, 0, set.size()), 0);
        EXPECT_EQ(header.time, 0.25);
        EXPECT_EQ(header.step, 40);
        if (world.rank() == 0) {
            // ParaView's reader of the index: one data set of every piece's points and arrays.
            auto reader = vtkSmartPointer<vtkXMLPUnstructuredGridReader>::New();
            reader->SetFileName((directory / "fluid.pvtu").c_str());
            reader->Update();
            vtkUnstructuredGrid* grid = reader->GetOutput();
            EXPECT_EQ(grid->GetNumberOfPoints(), 144);
            EXPECT_EQ(grid->GetNumberOfCells(), 144);
            for (const char* name : {"id", "density", "velocity", "patch", "tracer"})
                EXPECT_NE(grid->GetPointData()->GetArray(name), nullptr) << name;
            // The reader takes each piece's own arrays: that the index declares them as the pieces
            // store them (type and components) is checked against a piece's XML header.
            EXPECT_EQ(declaredPointArrays(directory / "fluid.pvtu"), declaredPointArrays(directory / "fluid_0.vtu"));
        }
    }
}

TEST(ParticlePieces, PiecesWithoutASerialOrderTakeTheOrderASerialRunReadsThemIn) {
    const Communicator world;
    for (const int writers : {world.size(), 1}) {
        const std::filesystem::path directory = sharedDirectory(world, "order" + std::to_string(writers));
        writeOnFirstRanks(world, writers, directory);
        MPI_Barrier(world.handle());
        StateHeader header;
        const ParticleSet<2> set = readParticlePieces<2>(world, directory / "fluid.pvtu", "fluid", header);
        ASSERT_TRUE(set.has(fields::orderCell) && set.has(fields::orderRank));
        std::vector<std::byte> mine;
        for (std::size_t i = 0; i < set.size(); ++i) {
            const std::array<std::int64_t, 3> entry{set.globalId[i], set[fields::orderCell][i], set[fields::orderRank][i]};
            const auto* bytes = reinterpret_cast<const std::byte*>(entry.data());
            mine.insert(mine.end(), bytes, bytes + sizeof(entry));
        }
        std::vector<std::size_t> fromRank;
        const std::vector<std::byte> all = world.gatherToFirst(mine, fromRank);
        if (world.rank() != 0) continue;
        std::map<std::int64_t, std::pair<std::int64_t, std::int64_t>> placeOfId;
        for (std::size_t at = 0; at < all.size(); at += sizeof(std::array<std::int64_t, 3>)) {
            std::array<std::int64_t, 3> entry;
            std::memcpy(entry.data(), all.data() + at, sizeof(entry));
            placeOfId[entry[0]] = {entry[1], entry[2]};
        }
        StateHeader serialHeader;
        const ParticleSet<2> serial = readParticleState<2>(directory / "fluid.pvtu", "fluid", serialHeader);
        ASSERT_EQ(placeOfId.size(), serial.size());
        for (std::size_t k = 0; k < serial.size(); ++k)
            EXPECT_EQ(placeOfId[serial.globalId[k]], std::make_pair(std::int64_t{0}, static_cast<std::int64_t>(k))) << writers << " writers";
    }
}

TEST(ParticlePieces, TwoParticlesOfOneIdOrPlaceOnDifferentRanksStopEveryRank) {
    const Communicator world;
    const auto share = [&] {
        ParticleSet<2> set("fluid");
        set.resize(3);
        for (std::size_t k = 0; k < 3; ++k) {
            set.globalId[k] = 10 * world.rank() + static_cast<std::int64_t>(k);
            set.position[k] = Vec<2>(0.01 * static_cast<double>(set.globalId[k]), 0.0);
        }
        return set;
    };
    const auto failure = [&](const ParticleSet<2>& set) {
        try {
            requireDistinctOverRanks(world, set, "fluid.vtu", true);
        } catch (const FatalError& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_EQ(failure(share()), "");
    const bool last = world.rank() == world.size() - 1;
    ParticleSet<2> sameId = share();
    if (last) sameId.globalId[2] = 0;               // rank 0's first
    const std::string idFailure = failure(sameId);  // collective: called once on every rank
    EXPECT_NE(idFailure.find("'fluid.vtu': two particles have the same id 0"), std::string::npos) << idFailure;
    ParticleSet<2> samePlace = share();
    if (last) samePlace.position[2] = Vec<2>(0.01, 0.0);  // rank 0's second
    const std::string expected = fmt::format("particle ids 1 and {} are at the same position (0.01 0)", 10 * (world.size() - 1) + 2);
    const std::string placeFailure = failure(samePlace);
    EXPECT_NE(placeFailure.find(expected), std::string::npos) << placeFailure;
    // Wall particles may coincide (patches that meet share a corner).
    EXPECT_NO_THROW(requireDistinctOverRanks(world, samePlace, "walls.vtu", false));
}

TEST(ParticlePieces, AMissingPieceStopsEveryRankNamingIt) {
    const Communicator world;
    const std::filesystem::path directory = sharedDirectory(world, "missing");
    writeOnFirstRanks(world, world.size(), directory);
    MPI_Barrier(world.handle());
    if (world.rank() == 0) std::filesystem::remove(directory / ("fluid_" + std::to_string(world.size() - 1) + ".vtu"));
    MPI_Barrier(world.handle());
    std::string caught;
    try {
        StateHeader header;
        readParticlePieces<2>(world, directory / "fluid.pvtu", "fluid", header);
    } catch (const FatalError& error) {
        caught = error.what();
    }
    EXPECT_NE(caught.find("names the piece 'fluid_" + std::to_string(world.size() - 1) + ".vtu', which is not there"), std::string::npos) << caught;
}

}  // namespace
}  // namespace sph::parallel
