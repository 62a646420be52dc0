#include "physics/FluidProperties.hpp"

#include "io/SelectByType.hpp"

#include <cmath>

namespace sph {

namespace {

double speedOfSound(const Dictionary& eosDict, double gravity) {
    const bool given = eosDict.found("c0"), derived = eosDict.found("c0FromHeight");
    if (given && derived) eosDict.fail("c0", "give either c0 or c0FromHeight, not both");
    if (given) return eosDict.getPositive("c0");
    if (!derived)
        throw FatalError(eosDict.where(), "dictionary '" + eosDict.name() +
                                              "' needs the speed of sound: 'c0 <value>;' or 'c0FromHeight { coefficient 10; height <H>; }'");
    const Dictionary& rule = eosDict.subDict("c0FromHeight");
    const double c0 = rule.getPositive("coefficient") * std::sqrt(gravity * rule.getPositive("height"));
    if (!(c0 > 0.0)) rule.fail("height", "c0FromHeight needs a non-zero gravity in constant/fluidProperties");
    return c0;
}

}  // namespace

template <int D>
FluidProperties<D> readFluidProperties(const Dictionary& dict) {
    const double rho0 = dict.getPositive("rho0");
    const double nu = dict.getNonNegativeOrDefault("nu", 0.0);
    const Vec<D> gravity = dict.getVector<D>("gravity");
    const double ramp = dict.getNonNegativeOrDefault("gravityRampTime", 0.0);
    const Dictionary& eosDict = dict.subDict("equationOfState");
    const double c0 = speedOfSound(eosDict, gravity.norm());
    const auto registry = makeEquationOfStateRegistry();
    EquationOfState eos = selectByType(registry, eosDict, eosDict, rho0, c0);
    return {rho0, nu, gravity, ramp, c0, std::move(eos)};
}

template FluidProperties<1> readFluidProperties<1>(const Dictionary&);
template FluidProperties<2> readFluidProperties<2>(const Dictionary&);
template FluidProperties<3> readFluidProperties<3>(const Dictionary&);

}  // namespace sph
