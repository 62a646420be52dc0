#include "io/ClosedCurves.hpp"

#include "core/FatalError.hpp"
#include "core/PlaneLoop.hpp"
#include "io/GeometryFile.hpp"

#include <fmt/format.h>

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkCutter.h>
#include <vtkPlane.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStripper.h>

#include <algorithm>
#include <limits>

namespace sph {

ClosedCurves ClosedCurves::read(const std::filesystem::path& file, double scale, double slice) {
    vtkSmartPointer<vtkPolyData> data = readGeometryFile(file, ".obj (polylines, or a surface to slice), .stl (a surface to slice)");
    // Polylines are the curves; a surface is cut at z = slice into segments.
    vtkSmartPointer<vtkPolyData> segments = data;
    if (data->GetNumberOfPolys() > 0) {
        auto plane = vtkSmartPointer<vtkPlane>::New();
        plane->SetOrigin(0.0, 0.0, slice);
        plane->SetNormal(0.0, 0.0, 1.0);
        auto cutter = vtkSmartPointer<vtkCutter>::New();
        cutter->SetInputData(data);
        cutter->SetCutFunction(plane);
        auto merge = vtkSmartPointer<vtkCleanPolyData>::New();  // the cut repeats a point per triangle
        merge->SetInputConnection(cutter->GetOutputPort());
        merge->Update();
        segments = merge->GetOutput();
    }
    if (segments->GetNumberOfLines() == 0)
        throw FatalError(data->GetNumberOfPolys() > 0
                             ? fmt::format("surface file '{}': its surface does not cross the plane z = {}", file.string(), slice)
                             : fmt::format("surface file '{}' holds no polyline (OBJ `l` lines) and no surface to slice", file.string()));
    auto stripper = vtkSmartPointer<vtkStripper>::New();
    stripper->SetInputData(segments);
    stripper->JoinContiguousSegmentsOn();
    stripper->SetMaximumLength(std::numeric_limits<int>::max() / 4);  // VTK's default (1000 points) would cut a long loop open
    stripper->Update();
    vtkPolyData* joined = stripper->GetOutput();
    ClosedCurves result;
    int openCurves = 0;
    vtkCellArray* lines = joined->GetLines();
    lines->InitTraversal();
    vtkIdType count;
    const vtkIdType* ids;
    while (lines->GetNextCell(count, ids)) {
        if (count < 4 || ids[0] != ids[count - 1]) {  // a loop repeats its first point; a triangle has 4 ids
            ++openCurves;
            continue;
        }
        std::vector<Vec<2>> loop;
        for (vtkIdType k = 0; k + 1 < count; ++k) {
            double x[3];
            joined->GetPoint(ids[k], x);
            loop.emplace_back(scale * x[0], scale * x[1]);
        }
        if (signedArea(loop) < 0.0) std::reverse(loop.begin(), loop.end());
        result.loops_.push_back(std::move(loop));
    }
    if (openCurves > 0)
        throw FatalError(fmt::format("surface file '{}': {} of its {} curves do not close (inside and outside are then undefined)", file.string(),
                                     openCurves, openCurves + static_cast<int>(result.loops_.size())));
    result.lower_ = Vec<2>::Constant(std::numeric_limits<double>::infinity());
    result.upper_ = -result.lower_;
    for (const auto& loop : result.loops_)
        for (const Vec<2>& x : loop) {
            result.lower_ = result.lower_.cwiseMin(x);
            result.upper_ = result.upper_.cwiseMax(x);
        }
    return result;
}

bool ClosedCurves::inside(const Vec<2>& x) const {
    bool inside = false;
    for (const auto& loop : loops_) inside = inside != insideLoop(loop, x);
    return inside;
}

double ClosedCurves::distance(const Vec<2>& x, Vec<2>& closest) const {
    double nearest2 = std::numeric_limits<double>::infinity();
    for (const auto& loop : loops_)
        for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
            const Vec<2> along = loop[i] - loop[j];
            const double t = along.squaredNorm() > 0.0 ? std::clamp((x - loop[j]).dot(along) / along.squaredNorm(), 0.0, 1.0) : 0.0;
            const Vec<2> onSegment = loop[j] + t * along;
            if (const double d2 = (x - onSegment).squaredNorm(); d2 < nearest2) {
                nearest2 = d2;
                closest = onSegment;
            }
        }
    return std::sqrt(nearest2);
}

}  // namespace sph
