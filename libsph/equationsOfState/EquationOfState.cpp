#include "equationsOfState/EquationOfState.hpp"

namespace sph {

EquationOfStateRegistry makeEquationOfStateRegistry() {
    EquationOfStateRegistry registry("equationOfState");
    registerEach(registry);
    return registry;
}

}  // namespace sph
