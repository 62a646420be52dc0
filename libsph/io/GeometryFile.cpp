#include "io/GeometryFile.hpp"

#include "core/FatalError.hpp"
#include "io/VtkErrors.hpp"

#include <fmt/format.h>

#include <vtkCleanPolyData.h>
#include <vtkOBJReader.h>
#include <vtkSTLReader.h>

#include <algorithm>
#include <cctype>

namespace sph {

vtkSmartPointer<vtkPolyData> readGeometryFile(const std::filesystem::path& file, const std::string& valid) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    vtkSmartPointer<vtkAbstractPolyDataReader> reader;
    if (extension == ".stl")
        reader = vtkSmartPointer<vtkSTLReader>::New();
    else if (extension == ".obj")
        reader = vtkSmartPointer<vtkOBJReader>::New();
    else
        throw FatalError(fmt::format("surface file '{}': unknown extension '{}'; valid: {}", file.string(), extension, valid));
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw FatalError(fmt::format("surface file '{}' does not exist", file.string()));
    vtkObject::GlobalWarningDisplayOff();
    VtkErrors errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors.callback);
    reader->SetFileName(file.c_str());
    auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
    clean->SetInputConnection(reader->GetOutputPort());
    clean->Update();
    if (!errors.text.empty() || reader->GetErrorCode() != 0)
        throw FatalError(fmt::format("surface file '{}' is not readable{}", file.string(), errors.text.empty() ? "" : ": " + errors.firstLine()));
    return clean->GetOutput();
}

}  // namespace sph
