// Reading an STL or OBJ geometry file by VTK, shared by io/TriangleSurface (3D) and
// io/ClosedCurves (2D); only io/ includes it, so no VTK type leaves io/.
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>

namespace sph {

// The file's polydata with coincident points merged (an STL repeats each vertex per triangle;
// polylines sharing an end then join). Throws FatalError naming the file for a missing or
// unreadable file and for an extension other than .stl and .obj (`valid` says what each is for).
vtkSmartPointer<vtkPolyData> readGeometryFile(const std::filesystem::path& file, const std::string& valid);

}  // namespace sph
