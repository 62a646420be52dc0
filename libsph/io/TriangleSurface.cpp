#include "io/TriangleSurface.hpp"

#include "core/FatalError.hpp"
#include "io/GeometryFile.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSelectEnclosedPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <map>
#include <utility>

namespace sph {

struct TriangleSurface::Queries {
    vtkSmartPointer<vtkPolyData> surface;  // what the two queries below search, held as long as they are
    vtkSmartPointer<vtkSelectEnclosedPoints> enclosed = vtkSmartPointer<vtkSelectEnclosedPoints>::New();
    vtkSmartPointer<vtkStaticCellLocator> locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    vtkSmartPointer<vtkGenericCell> cell = vtkSmartPointer<vtkGenericCell>::New();
};

TriangleSurface::TriangleSurface() : queries_(std::make_unique<Queries>()) {}
TriangleSurface::~TriangleSurface() {
    if (queries_) queries_->enclosed->Complete();
}
TriangleSurface::TriangleSurface(TriangleSurface&&) noexcept = default;

namespace {

// Reads, merges coincident points and triangulates.
vtkSmartPointer<vtkPolyData> readPolygons(const std::filesystem::path& file) {
    auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
    triangulate->SetInputData(readGeometryFile(file, ".stl (ASCII or binary), .obj"));
    // Orders every triangle's vertices the same way round (not yet outwards: see below).
    auto orient = vtkSmartPointer<vtkPolyDataNormals>::New();
    orient->SetInputConnection(triangulate->GetOutputPort());
    orient->ConsistencyOn();
    orient->SplittingOff();
    orient->ComputePointNormalsOff();
    orient->Update();
    vtkSmartPointer<vtkPolyData> surface = orient->GetOutput();
    if (surface->GetNumberOfPolys() == 0) throw FatalError(fmt::format("surface file '{}' holds no triangle", file.string()));
    return surface;
}

}  // namespace

TriangleSurface TriangleSurface::read(const std::filesystem::path& file, double scale) {
    vtkSmartPointer<vtkPolyData> surface = readPolygons(file);
    vtkPoints* points = surface->GetPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
        double x[3];
        points->GetPoint(i, x);
        points->SetPoint(i, scale * x[0], scale * x[1], scale * x[2]);
    }
    points->Modified();
    TriangleSurface result;
    std::map<std::pair<vtkIdType, vtkIdType>, int> edgeUses;
    double signedVolume = 0.0;
    vtkCellArray* polys = surface->GetPolys();
    polys->InitTraversal();
    vtkIdType count;
    const vtkIdType* ids;
    while (polys->GetNextCell(count, ids)) {
        if (count != 3) continue;
        Triangle t;
        for (int k = 0; k < 3; ++k) {
            double x[3];
            points->GetPoint(ids[k], x);
            (k == 0 ? t.a : k == 1 ? t.b : t.c) = Vec<3>(x[0], x[1], x[2]);
            ++edgeUses[std::minmax(ids[k], ids[(k + 1) % 3])];
        }
        const Vec<3> cross = (t.b - t.a).cross(t.c - t.a);
        t.area = 0.5 * cross.norm();
        if (!(t.area > 0.0)) continue;  // a degenerate triangle bounds nothing
        t.outward = cross.normalized();
        signedVolume += t.a.dot(t.b.cross(t.c)) / 6.0;
        result.triangles_.push_back(t);
    }
    const auto open = std::count_if(edgeUses.begin(), edgeUses.end(), [](const auto& use) { return use.second != 2; });
    if (open > 0)
        throw FatalError(
            fmt::format("surface file '{}' is not closed: {} of its {} edges do not join exactly two triangles "
                        "(inside and outside are then undefined)",
                        file.string(), open, edgeUses.size()));
    // Consistent order makes every normal outward or every one inward: the enclosed volume's sign says which.
    if (signedVolume < 0.0)
        for (Triangle& t : result.triangles_) {
            std::swap(t.b, t.c);
            t.outward = -t.outward;
        }
    double bounds[6];
    surface->GetBounds(bounds);
    result.lower_ = Vec<3>(bounds[0], bounds[2], bounds[4]);
    result.upper_ = Vec<3>(bounds[1], bounds[3], bounds[5]);
    result.queries_->surface = surface;
    result.queries_->enclosed->Initialize(surface);
    result.queries_->locator->SetDataSet(surface);
    result.queries_->locator->BuildLocator();
    return result;
}

bool TriangleSurface::inside(const Vec<3>& x) const {
    double point[3] = {x[0], x[1], x[2]};
    return queries_->enclosed->IsInsideSurface(point) != 0;
}

double TriangleSurface::distance(const Vec<3>& x, Vec<3>& closest) const {
    double point[3] = {x[0], x[1], x[2]}, nearest[3], distance2;
    vtkIdType cellId;
    int subId;
    queries_->locator->FindClosestPoint(point, nearest, queries_->cell, cellId, subId, distance2);
    closest = Vec<3>(nearest[0], nearest[1], nearest[2]);
    return std::sqrt(distance2);
}

}  // namespace sph
