// deficiencyWeights: the normalised blending weights wn_ij of the deficiency correction's
// published weighting (Jones, Yang & McCue-Weil 2010, Eq. 8) for three wall particles on a
// concave or convex arc, on a grid of points on the fluid side: the data of the paper's Fig. 6.
// Writes CSV rows x, y, wn_0, wn_1, wn_2 (each point's weights over the particles in its range).
#include "boundaryModels/DeficiencyWeightingJones2010.hpp"
#include "core/ExitOnError.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>

namespace {

constexpr const char* usage = R"(Usage: deficiencyWeights [OPTIONS]

Writes the deficiency correction's normalised weights of three wall particles on an arc
(Jones, Yang & McCue-Weil 2010, Fig. 6) on a grid of points on the fluid side.

Options (defaults: the paper's figure):
  -curvature concave|convex   the fluid inside (concave wall) or outside (convex) the arc [concave]
  -radius R                   radius of curvature [1]
  -spacing s                  wall particle spacing along the arc [0.25]
  -influenceRadius r          r_inf [0.775]
  -grid d                     grid spacing [0.01]
  -output file                CSV file [deficiencyWeights.csv]
  -help
)";

}  // namespace

int main(int argc, char** argv) {
    std::map<std::string, std::string> options{{"-curvature", "concave"},     {"-radius", "1"},  {"-spacing", "0.25"},
                                               {"-influenceRadius", "0.775"}, {"-grid", "0.01"}, {"-output", "deficiencyWeights.csv"}};
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-help" || arg == "--help") {
            fmt::print("{}", usage);
            return 0;
        }
        if (!options.count(arg) || i + 1 >= argc) {
            fmt::print(stderr, "error: unknown or incomplete option '{}'\n\n{}", arg, usage);
            return 2;
        }
        options[arg] = argv[++i];
    }
    return sph::exitCodeOf([&] {
        const auto number = [&](const std::string& option) {
            std::size_t used = 0;
            double value = 0.0;
            try {
                value = std::stod(options[option], &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != options[option].size() || !(value > 0.0))
                throw sph::FatalError("error: option " + option + ": expected a positive number, found '" + options[option] + "'");
            return value;
        };
        const std::string curvature = options["-curvature"];
        if (curvature != "concave" && curvature != "convex")
            throw sph::FatalError("error: option -curvature: expected concave or convex, found '" + curvature + "'");
        const double R = number("-radius"), s = number("-spacing"), rInf = number("-influenceRadius"), d = number("-grid");
        const bool concave = curvature == "concave";
        // The middle particle at the origin with normal (0, 1); the centre of the arc on the fluid
        // side for a concave wall, behind the wall for a convex one.
        const sph::Vec<2> centre(0.0, concave ? R : -R);
        std::array<sph::Vec<2>, 3> position;
        std::array<sph::Vec<2>, 3> normal;
        for (int k = 0; k < 3; ++k) {
            const double angle = (k - 1) * s / R;
            const sph::Vec<2> radial(std::sin(angle), concave ? -std::cos(angle) : std::cos(angle));
            position[static_cast<std::size_t>(k)] = centre + R * radial;
            normal[static_cast<std::size_t>(k)] = concave ? sph::Vec<2>(-radial) : radial;
        }
        std::ofstream out(options["-output"]);
        if (!out) throw sph::FatalError("error: cannot write '" + options["-output"] + "'");
        out << "x,y,wn_0,wn_1,wn_2\n";
        const int n = static_cast<int>(std::ceil((rInf + s) / d));
        std::size_t points = 0;
        for (int j = -n; j <= n; ++j)
            for (int i = -n; i <= n; ++i) {
                const sph::Vec<2> x(i * d, j * d);
                const double fromCentre = (x - centre).norm();
                if (concave ? fromCentre >= R : fromCentre <= R) continue;  // behind the wall
                std::array<double, 3> w{};
                double sum = 0.0;
                for (std::size_t k = 0; k < 3; ++k) {
                    const sph::Vec<2> r = x - position[k];
                    const double distance = r.norm();
                    if (distance >= rInf || distance == 0.0) continue;
                    w[k] = sph::DeficiencyWeightingJones2010::weight<2>(distance, sph::Vec<2>(r / distance), normal[k], s, s, rInf);
                    sum += w[k];
                }
                if (sum <= 0.0) continue;
                out << fmt::format("{:.5g},{:.5g},{:.5g},{:.5g},{:.5g}\n", x.x(), x.y(), w[0] / sum, w[1] / sum, w[2] / sum);
                ++points;
            }
        fmt::print("deficiencyWeights: {} wall, R {:g}, spacing {:g}, r_inf {:g}: {} points written to {}\n", curvature, R, s, rInf, points,
                   options["-output"]);
    });
}
