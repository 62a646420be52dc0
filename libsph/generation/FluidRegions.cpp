#include "generation/FluidRegions.hpp"

#include "core/MemoryBudget.hpp"
#include "core/PlaneLoop.hpp"
#include "generation/SurfaceShapes.hpp"
#include "io/SelectByType.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <map>

namespace sph {

LatticeAxis latticeAxis(const Dictionary& dict, const std::string& keyword, double lo, double hi, double dx) {
    const double cells = (hi - lo) / dx;
    const double whole = std::round(cells);
    if (!(whole >= 1.0))
        dict.fail(keyword, fmt::format("the extent {:g} (from {:g} to {:g}) must be at least half a spacing dx = {:g} (it is {:g} dx)", hi - lo, lo,
                                       hi, dx, cells));
    if (whole > maxSpacingsAcross)
        dict.fail(keyword, fmt::format("the extent {:g} is {:.3g} spacings dx = {:g} (at most {}): is the spacing a slip?", hi - lo, whole, dx,
                                       maxSpacingsAcross));
    return {lo, hi, dx, static_cast<int>(whole), std::abs(cells - whole) <= 1e-6 * std::max(1.0, whole)};
}

template <int D>
std::array<LatticeAxis, D> boxAxes(const Dictionary& dict, const Vec<D>& lo, const Vec<D>& hi, double dx, std::vector<std::string>& notes) {
    std::array<LatticeAxis, D> axes;
    for (int d = 0; d < D; ++d) {
        axes[static_cast<std::size_t>(d)] = latticeAxis(dict, "max", lo[d], hi[d], dx);
        if (const std::string note = axes[static_cast<std::size_t>(d)].note(d); !note.empty()) notes.push_back(note);
    }
    return axes;
}

template std::array<LatticeAxis, 1> boxAxes<1>(const Dictionary&, const Vec<1>&, const Vec<1>&, double, std::vector<std::string>&);
template std::array<LatticeAxis, 2> boxAxes<2>(const Dictionary&, const Vec<2>&, const Vec<2>&, double, std::vector<std::string>&);
template std::array<LatticeAxis, 3> boxAxes<3>(const Dictionary&, const Vec<3>&, const Vec<3>&, double, std::vector<std::string>&);

std::pair<long, long> LatticeShare::rows(long first, long last) const {
    const long rowCount = last - first + 1;
    return {first + rowCount * rank / count, first + rowCount * (rank + 1) / count - 1};
}

std::string LatticeAxis::note(int axis) const {
    if (whole) return "";
    const double last = count == 1 ? 0.0 : (hi - lo) / dx - (count - 1);
    return count == 1 ? fmt::format("the {} extent {:g} is {:g} dx: one particle, in its middle", "xyz"[axis], hi - lo, (hi - lo) / dx)
                      : fmt::format("the {} extent {:g} is {:g} dx: the last spacing is {:.3g} dx", "xyz"[axis], hi - lo, (hi - lo) / dx, last);
}

namespace {

// The lattice points of the share's rows, the first axis fastest.
template <int D>
void forEachLatticePoint(const std::array<LatticeAxis, D>& axes, const LatticeShare& share, const std::function<void(const Vec<D>&)>& visit) {
    constexpr auto last = static_cast<std::size_t>(D - 1);
    const auto [firstRow, lastRow] = share.rows(0, axes[last].count - 1);
    if (firstRow > lastRow) return;
    std::array<int, D> index{};
    index[last] = static_cast<int>(firstRow);
    while (true) {
        Vec<D> x;
        for (int d = 0; d < D; ++d) x[d] = axes[static_cast<std::size_t>(d)](index[static_cast<std::size_t>(d)]);
        visit(x);
        std::size_t d = 0;
        for (; d < last; ++d) {
            if (++index[d] < axes[d].count) break;
            index[d] = 0;
        }
        if (d == last && ++index[last] > lastRow) return;
    }
}

template <int D>
std::vector<Vec<D>> fillBox(const Dictionary& region, double dx, const LatticeShare& share, std::vector<std::string>& notes) {
    const Vec<D> lo = region.getVector<D>("min"), hi = region.getVector<D>("max");
    const std::array<LatticeAxis, D> axes = boxAxes<D>(region, lo, hi, dx, notes);
    const auto [firstRow, lastRow] = share.rows(0, axes.back().count - 1);
    double particles = static_cast<double>(std::max(0L, lastRow - firstRow + 1));
    for (std::size_t d = 0; d + 1 < axes.size(); ++d) particles *= axes[d].count;
    requireMemory(particles * solverBytesPerParticle,
                  fmt::format("{}: the fluid box of {:.3g} particles at spacing {:g}", region.where().str(), particles, dx));
    std::vector<Vec<D>> points;
    forEachLatticePoint<D>(axes, share, [&](const Vec<D>& x) { points.push_back(x); });
    return points;
}

// Lattice points of the whole domain (the share's rows) for which `inside` holds.
template <int D>
std::vector<Vec<D>> fillShape(double dx, const GenerationDomain<D>& domain, const std::function<bool(const Vec<D>&)>& inside) {
    std::array<LatticeAxis, D> axes;  // the domain's spacings, checked by the generator to fit an int
    for (int d = 0; d < D; ++d)
        axes[static_cast<std::size_t>(d)] = {domain.min[d], domain.max[d], dx, static_cast<int>(std::floor((domain.max[d] - domain.min[d]) / dx)),
                                             true};
    std::vector<Vec<D>> points;
    forEachLatticePoint<D>(axes, domain.share, [&](const Vec<D>& x) {
        if (inside(x)) points.push_back(x);
    });
    return points;
}

Vec<2> semiAxesOf(const Dictionary& region) {
    if (region.found("radius")) {
        const double r = region.getPositive("radius");
        return Vec<2>(r, r);
    }
    const Vec<2> axes = region.getVector<2>("semiAxes");
    if (!(axes.minCoeff() > 0.0)) region.fail("semiAxes", "both semi-axes must be greater than zero");
    return axes;
}

const CoefficientDoc velocityDoc{"velocity", "(0 0 0)",
                                 "a vector, or an analytic solution's field at t = 0: { type taylorGreen; ... } (-listModels analytic)"};

}  // namespace

void shapeForOtherDimensions(const Dictionary& dict, const std::string& what, const std::string& dimensions, int D) {
    throw FatalError(dict.entry("type").tokens().front().where,
                     fmt::format("{} type '{}' is for {} cases; this case is {}D", what, dict.get<std::string>("type"), dimensions, D));
}

template <int D>
FluidShapeRegistry<D> makeFluidShapeRegistry() {
    FluidShapeRegistry<D> registry("fluid region type");
    registry.add(
        "box",
        {"the box's own lattice, anchored at min; an extent not a whole number of dx adjusts the last spacing (dx/2 to 3dx/2, with a note); 1D-3D",
         "",
         {{"min", "", "lower corner"}, {"max", "", "upper corner"}, velocityDoc}},
        [](const Dictionary& region, double dx, const GenerationDomain<D>& domain, std::vector<std::string>& notes) {
            return fillBox<D>(region, dx, domain.share, notes);
        });
    const auto ellipse = [](const Dictionary& region, double dx, const GenerationDomain<D>& domain,
                            std::vector<std::string>&) -> std::vector<Vec<D>> {
        if constexpr (D == 2) {
            const Vec<2> centre = region.getVector<2>("centre");
            const Vec<2> axes = semiAxesOf(region);
            return fillShape<2>(dx, domain, [&](const Vec<2>& x) {
                return std::pow((x.x() - centre.x()) / axes.x(), 2) + std::pow((x.y() - centre.y()) / axes.y(), 2) < 1.0;
            });
        } else {
            shapeForOtherDimensions(region, "fluid region", "2D", D);
        }
    };
    registry.add("circle", {"the domain's lattice points inside a circle; 2D", "", {{"centre", "", "(x y)"}, {"radius", "", "[m]"}, velocityDoc}},
                 ellipse);
    registry.add("ellipse",
                 {"the domain's lattice points inside an ellipse; 2D", "", {{"centre", "", "(x y)"}, {"semiAxes", "", "(a b) [m]"}, velocityDoc}},
                 ellipse);
    registry.add("polygon", {"the domain's lattice points inside a closed polygon; 2D", "", {{"points", "", "((x y) ...), at least 3"}, velocityDoc}},
                 [](const Dictionary& region, double dx, const GenerationDomain<D>& domain, std::vector<std::string>&) -> std::vector<Vec<D>> {
                     if constexpr (D == 2) {
                         const std::vector<Vec<2>> polygon = region.getVectorList<2>("points");
                         if (polygon.size() < 3) region.fail("points", "a polygon needs at least 3 points");
                         return fillShape<2>(dx, domain, [&](const Vec<2>& x) { return insideLoop(polygon, x); });
                     } else {
                         shapeForOtherDimensions(region, "fluid region", "2D", D);
                     }
                 });
    registry.add("surface",
                 {"the domain's lattice points inside a closed surface from a file: 3D an STL or OBJ surface; 2D OBJ polylines, or a surface cut at "
                  "z = slice; 2D, 3D",
                  "",
                  {{"file", "", "STL or OBJ, relative to the case"},
                   {"scale", "1", "multiplies the file's coordinates"},
                   {"slice", "0", "2D: z of the cut through a surface"},
                   velocityDoc}},
                 [](const Dictionary& region, double dx, const GenerationDomain<D>& domain, std::vector<std::string>&) -> std::vector<Vec<D>> {
                     if constexpr (D >= 2)
                         return fillSurface<D>(region, dx, domain);
                     else
                         shapeForOtherDimensions(region, "fluid region", "2D and 3D", D);
                 });
    return registry;
}

template <int D>
FluidRegionParticles<D> fillFluidRegion(const Dictionary& region, double dx, const GenerationDomain<D>& domain) {
    FluidRegionParticles<D> result;
    // A vector, or an analytic solution's field: findSubDict would refuse the vector.
    if (const Entry* velocity = region.findEntry("velocity")) {
        if (velocity->isDictionary())
            result.initialField = selectByType(makeAnalyticSolutionRegistry<D>(), velocity->dictionary(), velocity->dictionary());
        else
            result.velocity = region.getVector<D>("velocity");
    }
    result.positions = selectByType(makeFluidShapeRegistry<D>(), region, region, dx, domain, result.notes);
    return result;
}

template FluidShapeRegistry<1> makeFluidShapeRegistry<1>();
template FluidShapeRegistry<2> makeFluidShapeRegistry<2>();
template FluidShapeRegistry<3> makeFluidShapeRegistry<3>();
template FluidRegionParticles<1> fillFluidRegion<1>(const Dictionary&, double, const GenerationDomain<1>&);
template FluidRegionParticles<2> fillFluidRegion<2>(const Dictionary&, double, const GenerationDomain<2>&);
template FluidRegionParticles<3> fillFluidRegion<3>(const Dictionary&, double, const GenerationDomain<3>&);

}  // namespace sph
