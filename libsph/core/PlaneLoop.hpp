// A closed loop of points in the plane (a polygon; the last point joins the first).
#pragma once

#include "core/Vector.hpp"

#include <vector>

namespace sph {

// Whether x is inside the loop (a ray from x crosses its edges an odd number of times).
inline bool insideLoop(const std::vector<Vec<2>>& loop, const Vec<2>& x) {
    bool inside = false;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const Vec<2>& a = loop[i];
        const Vec<2>& b = loop[j];
        if ((a.y() > x.y()) != (b.y() > x.y()) && x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x()) inside = !inside;
    }
    return inside;
}

// Positive when the loop runs counter-clockwise.
inline double signedArea(const std::vector<Vec<2>>& loop) {
    double twice = 0.0;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) twice += loop[j].x() * loop[i].y() - loop[i].x() * loop[j].y();
    return 0.5 * twice;
}

}  // namespace sph
