// The particle fields the library reads and writes, each named once with its type. Code asks a
// particle set for `fields::density`, never for "density": a misspelt field does not compile, and
// a scalar cannot be read as a vector. A field named at run time (one a user names in a
// dictionary, one read from a file) is a key made explicitly from its name, e.g. ScalarField{name}.
#pragma once

#include <string_view>

namespace sph {

struct VectorValued;  // Vec<D> in a particle set of dimension D

template <class Value>
struct FieldKey {
    constexpr explicit FieldKey(std::string_view fieldName) : name(fieldName) {}
    std::string_view name;
};

using ScalarField = FieldKey<double>;
using VectorField = FieldKey<VectorValued>;
using IntegerField = FieldKey<int>;

namespace fields {

// Every particle: the state and its rates.
inline constexpr VectorField velocity{"velocity"};
inline constexpr VectorField acceleration{"acceleration"};
inline constexpr ScalarField density{"density"};
inline constexpr ScalarField densityRate{"densityRate"};
inline constexpr ScalarField pressure{"pressure"};
inline constexpr ScalarField mass{"mass"};

// Wall particles: the surface they sample and what their patch's model sets.
inline constexpr IntegerField patch{"patch"};
inline constexpr IntegerField layer{"layer"};  // 0 for the layer nearest the fluid, counted into the wall
inline constexpr VectorField normal{"normal"};
inline constexpr ScalarField area{"area"};
inline constexpr ScalarField spacing{"spacing"};
inline constexpr VectorField viscousVelocity{"viscousVelocity"};
inline constexpr VectorField initialPosition{"initialPosition"};  // of a moving patch
inline constexpr VectorField initialNormal{"initialNormal"};
inline constexpr ScalarField initialArea{"initialArea"};
inline constexpr ScalarField initialSpacing{"initialSpacing"};

// The deficiency correction and the wall-force models.
inline constexpr VectorField uncorrectedAcceleration{"uncorrectedAcceleration"};
inline constexpr VectorField boundaryCorrection{"boundaryCorrection"};
inline constexpr ScalarField correctionCoefficient{"correctionCoefficient"};

// Integrators' history and particle shifting.
inline constexpr VectorField previousVelocity{"previousVelocity"};
inline constexpr ScalarField previousDensity{"previousDensity"};
inline constexpr VectorField shiftingVelocity{"shiftingVelocity"};
inline constexpr ScalarField freeSurfaceLambda{"freeSurfaceLambda"};

}  // namespace fields

}  // namespace sph
