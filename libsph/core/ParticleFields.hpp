// The particle fields the library reads and writes, each named once with its type. Code asks a
// particle set for `fields::density`, never for "density": a misspelt field does not compile, and
// a scalar cannot be read as a vector. A field named at run time (one a user names in a
// dictionary, one read from a file) is a key made explicitly from its name, e.g. ScalarField{name}.
#pragma once

#include <array>
#include <stdexcept>
#include <string_view>

namespace sph {

struct VectorValued;  // Vec<D> in a particle set of dimension D

// Every field the library names. A name's index here is its slot: a particle set finds a
// library field by its slot, without comparing names.
// clang-format off
inline constexpr std::array<std::string_view, 23> libraryFieldNames{
    // state and rates
    "velocity", "acceleration", "density", "densityRate", "pressure", "mass",
    // walls
    "patch", "layer", "normal", "area", "spacing", "viscousVelocity",
    "initialPosition", "initialNormal", "initialArea", "initialSpacing",
    // deficiency correction and wall forces
    "uncorrectedAcceleration", "boundaryCorrection", "correctionCoefficient",
    // integrators' history and particle shifting
    "previousVelocity", "previousDensity", "shiftingVelocity", "freeSurfaceLambda"};
// clang-format on

// -1 for a name the library does not use (a user's field).
constexpr int librarySlot(std::string_view name) {
    for (std::size_t slot = 0; slot < libraryFieldNames.size(); ++slot)
        if (libraryFieldNames[slot] == name) return static_cast<int>(slot);
    return -1;
}

template <class Value>
struct FieldKey {
    constexpr explicit FieldKey(std::string_view fieldName) : name(fieldName), slot(librarySlot(fieldName)) {}
    std::string_view name;
    int slot;
};

using ScalarField = FieldKey<double>;
using VectorField = FieldKey<VectorValued>;
using IntegerField = FieldKey<int>;

// A key of the library's own: does not compile unless its name is in libraryFieldNames.
template <class Value>
consteval FieldKey<Value> libraryField(std::string_view name) {
    if (librarySlot(name) < 0) throw std::logic_error("add the field's name to libraryFieldNames");
    return FieldKey<Value>(name);
}

namespace fields {

// Every particle: the state and its rates.
inline constexpr auto velocity = libraryField<VectorValued>("velocity");
inline constexpr auto acceleration = libraryField<VectorValued>("acceleration");
inline constexpr auto density = libraryField<double>("density");
inline constexpr auto densityRate = libraryField<double>("densityRate");
inline constexpr auto pressure = libraryField<double>("pressure");
inline constexpr auto mass = libraryField<double>("mass");

// Wall particles: the surface they sample and what their patch's model sets.
inline constexpr auto patch = libraryField<int>("patch");
inline constexpr auto layer = libraryField<int>("layer");  // 0 for the layer nearest the fluid, counted into the wall
inline constexpr auto normal = libraryField<VectorValued>("normal");
inline constexpr auto area = libraryField<double>("area");
inline constexpr auto spacing = libraryField<double>("spacing");
inline constexpr auto viscousVelocity = libraryField<VectorValued>("viscousVelocity");
inline constexpr auto initialPosition = libraryField<VectorValued>("initialPosition");  // of a moving patch
inline constexpr auto initialNormal = libraryField<VectorValued>("initialNormal");
inline constexpr auto initialArea = libraryField<double>("initialArea");
inline constexpr auto initialSpacing = libraryField<double>("initialSpacing");

// The deficiency correction and the wall-force models.
inline constexpr auto uncorrectedAcceleration = libraryField<VectorValued>("uncorrectedAcceleration");
inline constexpr auto boundaryCorrection = libraryField<VectorValued>("boundaryCorrection");
inline constexpr auto correctionCoefficient = libraryField<double>("correctionCoefficient");

// Integrators' history and particle shifting.
inline constexpr auto previousVelocity = libraryField<VectorValued>("previousVelocity");
inline constexpr auto previousDensity = libraryField<double>("previousDensity");
inline constexpr auto shiftingVelocity = libraryField<VectorValued>("shiftingVelocity");
inline constexpr auto freeSurfaceLambda = libraryField<double>("freeSurfaceLambda");

}  // namespace fields

}  // namespace sph
