// constant/fluidProperties: the fluid's physical properties.
//   rho0            1000;          // reference density [kg/m^3]
//   nu              1e-6;          // kinematic viscosity [m^2/s], optional (laminar viscosity needs it)
//   gravity         (0 -9.81);     // [m/s^2]
//   gravityRampTime 0;             // optional: gravity grows smoothly from 0 over this time [s]
//   equationOfState
//   {
//       type  tait;                // see -listModels
//       gamma 7;
//       c0    20;                  // speed of sound [m/s], or instead:
//       // c0FromHeight { coefficient 10; height 0.6; }   // c0 = coefficient sqrt(|g| height)
//   }
#pragma once

#include "core/Vector.hpp"
#include "equationsOfState/EquationOfState.hpp"
#include "io/Dictionary.hpp"
#include "physics/ModelContext.hpp"

#include <variant>

namespace sph {

template <int D>
struct FluidProperties {
    double rho0;
    double nu;
    Vec<D> gravity;
    double gravityRampTime;
    double c0;
    EquationOfState eos;
};

template <int D>
FluidProperties<D> readFluidProperties(const Dictionary& dict);

// What the models are built with, for spacing dx and smoothing length h.
template <int D>
ModelContext modelContext(const FluidProperties<D>& properties, double dx, double h) {
    return {dx,
            h,
            properties.c0,
            properties.rho0,
            properties.nu,
            std::visit([](const auto& e) { return e.stiffness(); }, properties.eos),
            std::visit([](const auto& e) { return e.exponent(); }, properties.eos)};
}

}  // namespace sph
