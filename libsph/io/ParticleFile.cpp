#include "io/ParticleFile.hpp"

#include "core/FatalError.hpp"
#include "io/AtomicFile.hpp"
#include "io/VtkErrors.hpp"
#include "io/VtuLayout.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <numeric>
#include <span>
#include <string_view>

namespace sph {

namespace {

template <class Array>
vtkSmartPointer<Array> fieldArray(const std::string& name, std::span<const double> values) {
    auto array = vtkSmartPointer<Array>::New();
    array->SetName(name.c_str());
    for (double v : values) array->InsertNextValue(v);
    return array;
}

// The written particles' values of one point field: `values` at each of `places`.
template <class Array, class Value>
vtkSmartPointer<Array> pointArray(const std::string& name, const std::vector<Value>& values, std::span<const std::uint32_t> places) {
    auto array = vtkSmartPointer<Array>::New();
    array->SetName(name.c_str());
    array->SetNumberOfValues(static_cast<vtkIdType>(places.size()));
    for (std::size_t i = 0; i < places.size(); ++i) array->SetValue(static_cast<vtkIdType>(i), values[places[i]]);
    return array;
}

constexpr std::string_view restartPrefix = "restart:";

vtkSmartPointer<vtkUnstructuredGrid> readGrid(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw FatalError("error: particle file '" + file.string() + "' does not exist");
    if (!std::filesystem::is_regular_file(file, ec))
        throw FatalError("error: particle file '" + file.string() + "' is not a regular file (a directory, a device?)");
    checkVtuLayout(file);
    // VTK's XML parser logs its errors itself; the reader's are collected and reported below.
    vtkObject::GlobalWarningDisplayOff();
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    VtkErrors errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors.callback);
    reader->SetFileName(file.c_str());
    reader->Update();
    if (!errors.text.empty() || reader->GetErrorCode() != 0 || !reader->GetOutput())
        throw FatalError("error: particle file '" + file.string() + "' is not a readable VTK unstructured grid" +
                         (errors.text.empty() ? std::string() : ": " + errors.firstLine()));
    return reader->GetOutput();
}

std::vector<double> numbers(vtkFieldData* data, const char* name) {
    std::vector<double> values;
    if (auto* array = vtkDoubleArray::SafeDownCast(data->GetAbstractArray(name)))
        for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i) values.push_back(array->GetValue(i));
    return values;
}

StateHeader headerOf(vtkUnstructuredGrid* grid, const std::filesystem::path& file) {
    vtkFieldData* data = grid->GetFieldData();
    StateHeader header;
    const auto required = [&](const char* name, std::size_t count) {
        std::vector<double> values = numbers(data, name);
        if (values.size() != count)
            throw FatalError("error: particle file '" + file.string() + "' lacks the field-data array '" + name +
                             "' (regenerate it with generateParticles)");
        return values;
    };
    header.dimension = static_cast<int>(required("dimension", 1)[0]);
    if (header.dimension < 1 || header.dimension > 3)
        throw FatalError("error: particle file '" + file.string() + "': dimension must be 1, 2 or 3, found " + std::to_string(header.dimension));
    header.time = required("TimeValue", 1)[0];
    header.step = static_cast<long>(required("step", 1)[0]);
    header.spacing = required("spacing", 1)[0];
    header.domainMin = required("domainMin", static_cast<std::size_t>(header.dimension));
    header.domainMax = required("domainMax", static_cast<std::size_t>(header.dimension));
    header.periodic = numbers(data, "periodic");
    header.patchLayers = numbers(data, "patchLayers");
    for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
        const char* name = data->GetArrayName(a);
        if (name && std::string_view(name).starts_with(restartPrefix)) header.restart[name + restartPrefix.size()] = numbers(data, name);
    }
    if (auto* integrator = vtkStringArray::SafeDownCast(data->GetAbstractArray("integrator")); integrator && integrator->GetNumberOfValues() == 1)
        header.integrator = integrator->GetValue(0);
    if (auto* names = vtkStringArray::SafeDownCast(data->GetAbstractArray("patchNames")))
        for (vtkIdType i = 0; i < names->GetNumberOfValues(); ++i) header.patchNames.push_back(names->GetValue(i));
    return header;
}

}  // namespace

template <int D>
void writeParticleFile(const std::filesystem::path& file, const ParticleSet<D>& particles, const StateHeader& header, WrittenPlaces places) {
    std::vector<std::uint32_t> owned;
    if (!places) {
        owned.resize(particles.ownedCount());
        std::iota(owned.begin(), owned.end(), 0u);
        places = owned;
    }
    const std::span<const std::uint32_t> written = *places;
    const std::size_t n = written.size();
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(n));
    for (std::size_t i = 0; i < n; ++i) {
        double p[3] = {0.0, 0.0, 0.0};
        for (int d = 0; d < D; ++d) p[d] = particles.position[written[i]][d];
        points->SetPoint(static_cast<vtkIdType>(i), p);
    }
    grid->SetPoints(points);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t i = 0; i < n; ++i) {
        const vtkIdType id = static_cast<vtkIdType>(i);
        cells->InsertNextCell(1, &id);
    }
    grid->SetCells(VTK_VERTEX, cells);

    grid->GetPointData()->AddArray(pointArray<vtkTypeInt64Array>("id", particles.globalId, written));
    for (const auto& [name, field] : particles.scalars())
        if (field.written) grid->GetPointData()->AddArray(pointArray<vtkDoubleArray>(name, field.values, written));
    for (const auto& [name, field] : particles.vectors()) {
        if (!field.written) continue;
        auto array = vtkSmartPointer<vtkDoubleArray>::New();
        array->SetName(name.c_str());
        array->SetNumberOfComponents(3);
        array->SetNumberOfTuples(static_cast<vtkIdType>(n));
        for (std::size_t i = 0; i < n; ++i) {
            double t[3] = {0.0, 0.0, 0.0};
            for (int d = 0; d < D; ++d) t[d] = field.values[written[i]][d];
            array->SetTuple(static_cast<vtkIdType>(i), t);
        }
        grid->GetPointData()->AddArray(array);
    }
    for (const auto& [name, field] : particles.integers())
        if (field.written) grid->GetPointData()->AddArray(pointArray<vtkIntArray>(name, field.values, written));

    vtkFieldData* data = grid->GetFieldData();
    const auto one = [](double value) { return std::vector<double>{value}; };
    data->AddArray(fieldArray<vtkDoubleArray>("TimeValue", one(header.time)));
    data->AddArray(fieldArray<vtkDoubleArray>("step", one(static_cast<double>(header.step))));
    data->AddArray(fieldArray<vtkDoubleArray>("dimension", one(static_cast<double>(D))));
    data->AddArray(fieldArray<vtkDoubleArray>("spacing", one(header.spacing)));
    data->AddArray(fieldArray<vtkDoubleArray>("domainMin", header.domainMin));
    data->AddArray(fieldArray<vtkDoubleArray>("domainMax", header.domainMax));
    if (!header.periodic.empty()) data->AddArray(fieldArray<vtkDoubleArray>("periodic", header.periodic));
    if (!header.patchLayers.empty()) data->AddArray(fieldArray<vtkDoubleArray>("patchLayers", header.patchLayers));
    for (const auto& [key, values] : header.restart) data->AddArray(fieldArray<vtkDoubleArray>(std::string(restartPrefix) + key, values));
    const auto addStrings = [&](const char* name, const std::vector<std::string>& values) {
        auto strings = vtkSmartPointer<vtkStringArray>::New();
        strings->SetName(name);
        for (const std::string& value : values) strings->InsertNextValue(value);
        data->AddArray(strings);
    };
    if (!header.integrator.empty()) addStrings("integrator", {header.integrator});
    if (!header.patchNames.empty()) addStrings("patchNames", header.patchNames);

    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
        VtkErrors errors;
        writer->AddObserver(vtkCommand::ErrorEvent, errors.callback);
        writer->SetFileName(temporary.c_str());
        writer->SetInputData(grid);
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        writer->SetCompressorTypeToZLib();
        if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError || !errors.text.empty())
            throw FatalError("error: cannot write particle file '" + file.string() + "'" + (errors.text.empty() ? "" : ": " + errors.firstLine()));
    });
}

template <int D>
ParticleSet<D> readParticleFile(const std::filesystem::path& file, const std::string& setName, StateHeader& header) {
    vtkSmartPointer<vtkUnstructuredGrid> grid = readGrid(file);
    header = headerOf(grid, file);
    if (header.dimension != D)
        throw FatalError("error: particle file '" + file.string() + "' is " + std::to_string(header.dimension) + "D, expected " + std::to_string(D) +
                         "D");
    const vtkIdType n = grid->GetNumberOfPoints();
    ParticleSet<D> set(setName);
    set.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i) {
        double p[3];
        grid->GetPoint(i, p);
        for (int d = 0; d < D; ++d) set.position[static_cast<std::size_t>(i)][d] = p[d];
    }
    vtkPointData* pointData = grid->GetPointData();
    bool hasIds = false;
    for (int a = 0; a < pointData->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = pointData->GetArray(a);
        if (!array || !array->GetName()) continue;
        const std::string name = array->GetName();
        if (array->GetNumberOfTuples() != n)
            throw FatalError("error: particle file '" + file.string() + "': array '" + name + "' has " + std::to_string(array->GetNumberOfTuples()) +
                             " values for " + std::to_string(n) + " particles");
        if (name == "id") {
            hasIds = true;
            for (vtkIdType i = 0; i < n; ++i) set.globalId[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(array->GetTuple1(i));
        } else if (vtkIntArray::SafeDownCast(array)) {
            auto& values = set.add(IntegerField{name}, 0);
            for (vtkIdType i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = static_cast<int>(array->GetTuple1(i));
        } else if (array->GetNumberOfComponents() == 1) {
            auto& values = set.add(ScalarField{name}, 0.0);
            for (vtkIdType i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = array->GetTuple1(i);
        } else if (array->GetNumberOfComponents() == 3) {
            auto& values = set.add(VectorField{name}, Vec<D>::Zero());
            for (vtkIdType i = 0; i < n; ++i) {
                const double* t = array->GetTuple3(i);
                for (int d = 0; d < D; ++d) values[static_cast<std::size_t>(i)][d] = t[d];
            }
        }
    }
    if (!hasIds) throw FatalError("error: particle file '" + file.string() + "' has no 'id' array");
    return set;
}

StateHeader readParticleFileHeader(const std::filesystem::path& file) { return headerOf(readGrid(file), file); }

#define SPHKIT_INSTANTIATE(D)                                                                                                   \
    template void writeParticleFile<D>(const std::filesystem::path&, const ParticleSet<D>&, const StateHeader&, WrittenPlaces); \
    template ParticleSet<D> readParticleFile<D>(const std::filesystem::path&, const std::string&, StateHeader&);
SPHKIT_INSTANTIATE(1)
SPHKIT_INSTANTIATE(2)
SPHKIT_INSTANTIATE(3)
#undef SPHKIT_INSTANTIATE

}  // namespace sph
